// What grass.image and grass.volume declare and record to draw a field as macro-cells
// (macro_cells.hpp): the field's cells as a storage buffer of GrassCell, one instance record per
// macro-cell and the field's placement, uploaded at load; one quad or cuboid per macro-cell drawn
// every frame.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "graph/raster_state.hpp"

#include "grass_field.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace canopy::grass {

namespace macro_names {
inline constexpr const char* kCells = "field_cells";  // GrassCell per field cell (storage)
inline constexpr const char* kMacros = "macros";      // vec4 per macro-cell: first cell x, z; span x, z (vertex, per instance)
inline constexpr const char* kField = "macro_field";  // GrassMacroField (uniform)
// On a terrain only (BufferDecl::only_on_terrain; 16 bytes on flat ground):
inline constexpr const char* kHeights = "field_heights";  // float per grid vertex (storage, binding 5)
inline constexpr const char* kRanges = "macro_ranges";    // vec2 per macro-cell: its grid's lowest and highest height (storage, binding 6)
}  // namespace macro_names

// How macro-cells follow a terrain (the first grass population's, when it stands on one; a flat
// field draws as without). Every macro shader on a terrain reads the field's grid heights
// (macro_names::kHeights).
struct MacroTerrain {
    // Split a macro-cell whose ground departs from the bilinear patch of its corners by more than
    // this, world units (macro_instances_on_terrain: grass.image's quads, which follow their
    // corners alone); none: never (grass.volume's cuboids, whose rays read the ground under every hit).
    std::optional<float> max_unplanarity;
    // Upload each macro-cell's height range (macro_names::kRanges: the volume's cuboids span it).
    bool height_ranges = false;
    // Set at load to the macro-cells uploaded (splits add some), which the frame pass draws.
    std::shared_ptr<uint32_t> count = std::make_shared<uint32_t>(0);
};

// Whether the macro-cells follow a terrain: the first grass population stands on one.
bool macros_on_terrain(std::span<const GeneratedPopulation> populations);

// The field's grid heights (macro_names::kHeights), one float a grid vertex, on a terrain only;
// `host_visible` for a reader on the CPU (the quadtree's traversal).
BufferDecl grid_heights_buffer(bool host_visible);

// Writes `grass`'s grid heights (grid_heights) into that buffer at load, and returns them.
std::vector<float> upload_grid_heights(PassContext& pc, const GrassField& field, const GeneratedPopulation& grass);

// Declares the buffers: field_cells and macros sized by the scene's copies, the field, and the
// terrain's heights and (with `terrain.height_ranges`) ranges.
void declare_macro_buffers(FrameGraph& graph, const MacroTerrain& terrain);

// The load-phase copy pass that fills them from the first grass population (nothing without
// one). Macro-cells draw the first grass population only, as the bakes show only its patch.
PassDecl macro_setup_pass(uint32_t k, const MacroTerrain& terrain);

// `vertex` records (QuadVertex: locations 0-1, binding 0) and a macro-cell's MacroInstance per
// instance at location 2 (binding 1, uvec4 in the shaders).
VertexLayout macro_layout();

// The uses a macro frame pass adds: the field (uniform, binding 3), its cells (storage, 4), the
// macro-cells (vertex), the heights (storage, 5) and, with `terrain.height_ranges`, the ranges (6).
void use_macro_buffers(PassDecl& pass, const MacroTerrain& terrain);

// What a macro frame pass records: the scene's objects with `ground`, then `vertex_count`
// vertices of `vertex_buffer` once per macro-cell the setup uploaded, drawn with `flat` or, on a
// terrain (macros_on_terrain), `on_terrain`.
void record_ground_and_macros(PassContext& pc, const RasterState& ground, const RasterState& flat,
                              const RasterState& on_terrain, const std::string& vertex_buffer, uint32_t vertex_count,
                              const MacroTerrain& terrain);

}  // namespace canopy::grass
