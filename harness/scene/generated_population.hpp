// A population as the raster side receives it (PassContext::populations): what to draw, its
// prototype's triangles and every generated copy, the very copies the reference traces.
#pragma once

#include "scene/geometry.hpp"
#include "scene/population.hpp"
#include "scene/population_kind.hpp"

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace canopy {

// A population's copies as the raster side reads them: shared with the scene's population that
// generated them (not copied), read like a const vector.
class PopulationCopies {
public:
    PopulationCopies() = default;
    explicit PopulationCopies(std::shared_ptr<const std::vector<PopulationInstance>> copies) : copies_(std::move(copies)) {}
    size_t size() const { return copies_ ? copies_->size() : 0; }
    bool empty() const { return size() == 0; }
    const PopulationInstance* data() const { return copies_ ? copies_->data() : nullptr; }
    const PopulationInstance& operator[](size_t i) const { return (*copies_)[i]; }
    const PopulationInstance* begin() const { return data(); }
    const PopulationInstance* end() const { return data() + size(); }
    operator std::span<const PopulationInstance>() const { return {data(), size()}; }

private:
    std::shared_ptr<const std::vector<PopulationInstance>> copies_;
};

struct GeneratedPopulation {
    std::string name;
    std::string kind;
    Material material;  // the prototype's
    bool casts_shadows = true;
    TriangleMesh prototype;                   // local space, as in build_scene_meshes
    PopulationCopies instances;                 // generate_instances
    std::vector<PopulationVertexData> vertex_data;  // a family's kind: one per prototype vertex; else empty
    ParamSet params;  // a family's kind: the population's parameters (Population::params)
    float transmission = 0.0f;  // FamilyPopulation::transmission
    bool on_terrain = false;    // stands on a heightfield (Population::ground.terrain): a technique may
                                // then draw geometry that follows it, and keep the cheaper one otherwise
};

// The scene's populations whose kind is one of `kinds`, in scene order; `meshes` as
// build_scene_meshes returns them.
std::vector<GeneratedPopulation> generate_populations(const Scene& scene, const std::vector<TriangleMesh>& meshes,
                                                      const std::vector<std::string>& kinds);

}  // namespace canopy
