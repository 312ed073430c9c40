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

// The field's placement for the macro shaders; `top`: the bake frame's top (patch units);
// `transmission`: the population's (FamilyPopulation::transmission).
shader::GrassMacroField macro_field(const GrassField& field, uint32_t k, float top, float transmission);

}  // namespace canopy::grass
