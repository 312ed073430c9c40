// The grass field as a scene population (kind "grass"): a [[population]] with kind = "grass"
// and its `params` describe the blade patch and the field of cells it is tiled over; the
// family generates the patch (blade_patch.hpp) and one copy per cell (mirrored, thinned by
// the cell's corner densities), and the Embree reference traces the very same blades, cut by
// the same outline (shaders/blade_alpha.h) and thinned by the same test (shaders/grass_density.h).
#pragma once

#include "blade_patch.hpp"
#include "grass_field.hpp"

#include "core/param.hpp"
#include "scene/population_kind.hpp"

namespace canopy::grass {

inline constexpr const char* kGrassPopulationKind = "grass";

// The kind's parameters, as `canopy list` prints them.
std::vector<ParamSpec> grass_population_params();

// The patch and field that parameters describe (throws std::invalid_argument like validate()).
struct GrassPopulationSpec {
    BladePatchParams patch;
    GrassField field;
    float taper = 2.0f;  // the outline's taper exponent k (blade_alpha.h)
    float transmission = 0.0f;  // Boulanger eq 4.1's gamma (FamilyPopulation::transmission)
};
GrassPopulationSpec grass_population_spec(const ParamSet& params, const PopulationGround& ground = {});
// Its field's cells, size, corner and mirror alone, without the density map (cheap: per frame).
GrassField grass_field_placement(const ParamSet& params);

// Copy c is cell (c % cells.x, c / cells.x). Its model matrix maps the patch's unit square onto
// the cell, mirrored about the patch centre by the cell's signs; its data are the cell's corner
// densities in patch order. On a terrain the model lifts the cell to its (x0, z0) corner's height
// and the normal matrix's w components carry the other corners' (shaders/grass_terrain.h); the
// reference lifts each blade the same way (FamilyPopulation::vertex_offset). Per vertex: data[0] = (u, v, threshold, colour), data[1] =
// (root x, root z, taper, 0) in patch coordinates (shaders/grass_population.glsl reads them).
FamilyPopulation generate_grass_population(const GrassPopulationSpec& spec);

}  // namespace canopy::grass
