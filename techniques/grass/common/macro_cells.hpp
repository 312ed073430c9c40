// What grass.image and grass.volume declare and upload to draw a field as Lemme's macro-cells
// (§6.2, shaders/grass_macro_cells.h): k x k cells per quad or cuboid, the field's cells as a
// storage buffer of GrassCell, and one instance record per macro-cell.
#pragma once

#include "grass_field.hpp"

#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "graph/raster_state.hpp"
#include "scene/population.hpp"

#include "../shaders/grass_macro_cells.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace canopy::grass {

namespace macro_names {
inline constexpr const char* kCells = "field_cells";  // GrassCell per field cell (storage)
inline constexpr const char* kMacros = "macros";      // vec4 per macro-cell: first cell x, z; span x, z (vertex, per instance)
inline constexpr const char* kField = "macro_field";  // GrassMacroField (uniform)
}  // namespace macro_names

// The macro-cells of size k over a cells.x x cells.y field, in row order: (first x, first z,
// span x, span z); those at the field's far edges are cut to it (Lemme L736: "not necessarily
// equal"). k = 1: one per cell.
std::vector<glm::vec4> macro_instances(glm::uvec2 cells, uint32_t k);
uint32_t macro_count(glm::uvec2 cells, uint32_t k);  // macro_instances(cells, k).size()

// Every field cell as a macro-cell reads it, in the population's copy order (cell
// (c % cells.x, c / cells.x)): its mirror signs and the corner densities its copy carries.
std::vector<shader::GrassCell> grass_cells(const GrassField& field, std::span<const PopulationInstance> copies);

// The field's placement for the macro shaders; `top`: the bake frame's top (patch units).
shader::GrassMacroField macro_field(const GrassField& field, uint32_t k, float top);

// Declares the three buffers (field_cells and macros sized by the scene's copies).
void declare_macro_buffers(FrameGraph& graph);

// The load-phase copy pass that fills them from the first grass population (nothing without
// one); `top` as macro_field's, from the prototype's bounds.
PassDecl macro_setup_pass(uint32_t k);

// `vertex` records (QuadVertex: locations 0-1, binding 0) and a macro-cell's vec4 per instance at
// location 2 (binding 1).
VertexLayout macro_layout();

// What a macro frame pass records: the scene's objects with `ground`, then `vertex_count`
// vertices of `vertex_buffer` once per macro-cell of size k of the first grass population.
void record_ground_and_macros(PassContext& pc, const RasterState& ground, const RasterState& over,
                              const std::string& vertex_buffer, uint32_t vertex_count, uint32_t k);

}  // namespace canopy::grass
