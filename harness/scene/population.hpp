// A population: many copies of one prototype that the scene describes as a rule rather than as a
// list of objects (a grass field, a forest). Techniques that declare its kind in
// GraphNeeds::populations render it in their own way; the Embree reference renders every copy
// as ground truth. Both get the copies from generate_instances, so they see the same ones.
#pragma once

#include "scene/object.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace canopy {

// The population kinds the harness knows (what a [[population]]'s `kind` may be).
namespace population_kinds {
inline constexpr const char* kScatter = "scatter";  // copies scattered over a rectangle of ground
}  // namespace population_kinds

// An alpha mask cut into every copy (harness/shaders/alpha_mask.h), in the prototype's mesh space:
// both renderers evaluate the same function at the same points.
struct AlphaMask {
    enum class Kind { none, stripes };
    Kind kind = Kind::none;
    int axis = 0;           // 0 x, 1 y, 2 z
    float period = 1.0f;    // > 0
    float opaque = 1.0f;    // fraction of each period that stays, in (0, 1]
    glm::vec4 packed() const;  // the shader's vec4
};

// A scatter population: `count` copies of `prototype`, each placed at a uniformly random point of
// the rectangle [region_min, region_max] (x, z) at height `ground_y`, turned by a random yaw about
// +y (when random_yaw) and scaled uniformly by a factor drawn from [scale_min, scale_max].
// A copy's world matrix is placement * prototype.instances[0].matrix(): the prototype's own
// transform (e.g. a translate lifting a box onto the ground) applies first.
struct Population {
    std::string name;
    std::string kind = population_kinds::kScatter;
    Object prototype;  // shape, sizes, material, casts_shadows; exactly one instance (its own transform)
    uint32_t count = 1;
    glm::vec2 region_min{-1.0f, -1.0f};  // x, z
    glm::vec2 region_max{1.0f, 1.0f};
    float ground_y = 0.0f;
    uint64_t seed = 0;
    float scale_min = 1.0f;
    float scale_max = 1.0f;
    bool random_yaw = true;
    AlphaMask alpha_mask;
    SourceLocation where;
};

// One generated copy: its world matrix and the inverse-transpose of its linear part (for normals),
// laid out as DrawConstants' model and normal_matrix, and the population's alpha mask, so a vertex
// shader reads it as per-instance attributes (harness/shaders/population.vert).
struct PopulationInstance {
    glm::mat4 model{1.0f};
    glm::vec4 normal_matrix[3]{glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0)};
    glm::vec4 alpha_mask{0.0f};  // AlphaMask::packed(), the same for every copy
};
static_assert(sizeof(PopulationInstance) == 128, "population.vert reads 8 vec4 per instance");

// The placement (translate, yaw, scale; without the prototype's own transform) of copy `index`.
// Deterministic and portable: a splitmix64 hash of (seed, index, draw) feeds each random number,
// so copy `index` is the same whatever `count` is, on every standard library.
glm::mat4 scatter_placement(const Population& population, uint32_t index);

// Every copy, in index order: count entries.
std::vector<PopulationInstance> generate_instances(const Population& population);

// The scene's populations whose kind is one of `kinds` (indices into scene.populations).
std::vector<size_t> populations_of_kinds(const std::vector<Population>& populations,
                                         const std::vector<std::string>& kinds);

}  // namespace canopy
