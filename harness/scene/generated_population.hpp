// A population as the raster side receives it (PassContext::populations): what to draw, its
// prototype's triangles and every generated copy, the very copies the reference traces.
#pragma once

#include "scene/geometry.hpp"
#include "scene/population.hpp"
#include "scene/population_kind.hpp"

#include <string>
#include <vector>

namespace canopy {

struct GeneratedPopulation {
    std::string name;
    std::string kind;
    Material material;  // the prototype's
    bool casts_shadows = true;
    TriangleMesh prototype;                   // local space, as in build_scene_meshes
    std::vector<PopulationInstance> instances;  // generate_instances
    std::vector<PopulationVertexData> vertex_data;  // a family's kind: one per prototype vertex; else empty
    ParamSet params;  // a family's kind: the population's parameters (Population::params)
    float transmission = 0.0f;  // FamilyPopulation::transmission
};

// The scene's populations whose kind is one of `kinds`, in scene order; `meshes` as
// build_scene_meshes returns them.
std::vector<GeneratedPopulation> generate_populations(const Scene& scene, const std::vector<TriangleMesh>& meshes,
                                                      const std::vector<std::string>& kinds);

}  // namespace canopy
