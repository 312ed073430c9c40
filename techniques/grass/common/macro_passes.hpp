// What grass.image and grass.volume declare and record to draw a field as macro-cells
// (macro_cells.hpp): the field's cells as a storage buffer of GrassCell, one instance record per
// macro-cell and the field's placement, uploaded at load; one quad or cuboid per macro-cell drawn
// every frame.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "graph/raster_state.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace canopy::grass {

namespace macro_names {
inline constexpr const char* kCells = "field_cells";  // GrassCell per field cell (storage)
inline constexpr const char* kMacros = "macros";      // vec4 per macro-cell: first cell x, z; span x, z (vertex, per instance)
inline constexpr const char* kField = "macro_field";  // GrassMacroField (uniform)
inline constexpr const char* kHeights = "field_heights";  // float per grid vertex (storage; on a terrain)
}  // namespace macro_names

// Macro-cells that follow a terrain (grass.image's): each quad's corners lifted onto the field's
// grid heights (macro_names::kHeights), and macro-cells whose ground is not flat enough split
// (macro_instances_on_terrain). `count` is set at load to the macro-cells uploaded, which the
// frame pass draws.
struct MacroTerrain {
    float max_unplanarity = 0.05f;  // world units
    std::shared_ptr<uint32_t> count = std::make_shared<uint32_t>(0);
};

// Declares the three buffers (field_cells and macros sized by the scene's copies) and, with
// `terrain`, the grid heights.
void declare_macro_buffers(FrameGraph& graph, bool terrain = false);

// The load-phase copy pass that fills them from the first grass population (nothing without
// one). Macro-cells draw the first grass population only, as the bakes show only its patch.
PassDecl macro_setup_pass(uint32_t k, const std::optional<MacroTerrain>& terrain = std::nullopt);

// `vertex` records (QuadVertex: locations 0-1, binding 0) and a macro-cell's MacroInstance per
// instance at location 2 (binding 1, uvec4 in the shaders).
VertexLayout macro_layout();

// What a macro frame pass records: the scene's objects with `ground`, then `vertex_count`
// vertices of `vertex_buffer` once per macro-cell of size k of the first grass population.
// With `terrain`, the macro-cells its setup counted.
void record_ground_and_macros(PassContext& pc, const RasterState& ground, const RasterState& over,
                              const std::string& vertex_buffer, uint32_t vertex_count, uint32_t k,
                              const std::optional<MacroTerrain>& terrain = std::nullopt);

}  // namespace canopy::grass
