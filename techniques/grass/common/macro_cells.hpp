// Lemme's macro-cells (§6.2, shaders/grass_macro_cells.h) as data: the macro-cells that tile a
// field, and each field cell's record (mirror signs, corner densities) a macro-cell reads.
// Pure CPU; the frame-graph pieces that upload and draw them are in macro_passes.hpp.
#pragma once

#include "grass_field.hpp"

#include "scene/population.hpp"

#include "../shaders/grass_macro_cells.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace canopy::grass {

// One macro-cell as the macro shaders read it per instance: first cell x, z; span x, z (16-bit:
// a field is at most 4096 cells a side).
using MacroInstance = glm::u16vec4;

// The macro-cells of size k over a cells.x x cells.y field, in row order; those at the field's
// far edges are cut to it (Lemme L736: "not necessarily equal"). k = 1: one per cell.
std::vector<MacroInstance> macro_instances(glm::uvec2 cells, uint32_t k);
uint32_t macro_count(glm::uvec2 cells, uint32_t k);  // macro_instances(cells, k).size()

// Every field cell as a macro-cell reads it, in the population's copy order (cell
// (c % cells.x, c / cells.x)): its mirror signs and the corner densities its copy carries.
std::vector<shader::GrassCell> grass_cells(const GrassField& field, std::span<const PopulationInstance> copies);

// The heights of the field's grid vertices (cell corners) above its origin, (cells.x + 1) x
// (cells.y + 1) in rows along x, read back from the copies' terrain packing (grass_terrain.h: the
// model's lift to the cell's (x0, z0) corner, the other corners above it in the normal matrix's w);
// zeros for a flat field.
std::vector<float> grid_heights(const GrassField& field, std::span<const PopulationInstance> copies);

// How far the ground under macro-cell `m` departs from the bilinear patch through its four
// corners: the largest difference at a grid vertex inside it (Lemme's unplanarity, L906); 0 for
// one cell, whose two triangles the quad follows exactly.
float macro_unplanarity(std::span<const float> grid, glm::uvec2 cells, MacroInstance m);

// The lowest and highest grid height under macro-cell `m` (its (span + 1)^2 grid vertices): the
// ground's own extremes, since each of its triangles lies between its vertices.
glm::vec2 macro_height_range(std::span<const float> grid, glm::uvec2 cells, MacroInstance m);

// macro_instances on a terrain: a macro-cell whose unplanarity exceeds `max_unplanarity` is split in
// four (spans halved, rounded up), and so on until each part is under it or one cell (Lemme's lod
// test that splits cells until their unplanarity falls below a threshold, L906-908). Parts follow
// their macro-cell in the list; on flat ground the list is macro_instances'.
std::vector<MacroInstance> macro_instances_on_terrain(glm::uvec2 cells, uint32_t k, std::span<const float> grid,
                                                      float max_unplanarity);

// The field's placement for the macro shaders; `top`: the bake frame's top (patch units);
// `transmission`: the population's (FamilyPopulation::transmission).
shader::GrassMacroField macro_field(const GrassField& field, uint32_t k, float top, float transmission);

}  // namespace canopy::grass
