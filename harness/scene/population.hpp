// A population: many copies of one prototype that the scene describes as a rule rather than as a
// list of objects (a grass field, a forest). Techniques that declare its kind in
// GraphNeeds::populations render it in their own way; the Embree reference renders every copy
// as ground truth. Both get the copies from generate_instances, so they see the same ones.
#pragma once

#include "core/param.hpp"
#include "scene/object.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace canopy {

// The population kind the harness itself knows; technique families register more
// (scene/population_kind.hpp), e.g. the grass family's "grass".
namespace population_kinds {
inline constexpr const char* kScatter = "scatter";  // copies scattered over a rectangle of ground
}  // namespace population_kinds

struct FamilyPopulation;  // scene/population_kind.hpp

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
// What a family's population stands on: the scene's heightfield object its `terrain` key names
// (moved by a translation alone), or nothing: the kind's own ground.
struct PopulationGround {
    std::shared_ptr<const HeightField> terrain;  // local heights, centred on `origin` in x and z
    glm::vec3 origin{0.0f};                      // the heightfield object's translation
    std::string name;                            // the object's, for messages
    // World height of the terrain at a world (x, z); 0 without a terrain.
    float height_at(glm::vec2 world_xz) const;
};

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

    // A family's kind (not scatter): its parameters as the config gave them, defaults filled in,
    // and what they generate, made once when the scene is read (its prototype's triangles,
    // per-vertex data, copies and alpha test). The scatter fields above are then unused but for
    // prototype.material and prototype.casts_shadows.
    ParamSet params;
    std::shared_ptr<const FamilyPopulation> family;
    PopulationGround ground;  // the `terrain` key's heightfield, or none
};

// One generated copy: its world matrix and the inverse-transpose of its linear part (for normals),
// laid out as DrawConstants' model and normal_matrix, and four floats of per-copy data, so a
// vertex shader reads it as per-instance attributes (harness/shaders/population.vert).
struct PopulationInstance {
    glm::mat4 model{1.0f};
    glm::vec4 normal_matrix[3]{glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0)};
    // scatter: AlphaMask::packed(), the same for every copy; a family's kind: what its shaders
    // read per copy (e.g. the grass cell's corner densities).
    glm::vec4 data{0.0f};
};
static_assert(sizeof(PopulationInstance) == 128, "population.vert reads 8 vec4 per instance");

// The placement (translate, yaw, scale; without the prototype's own transform) of copy `index`.
// Deterministic and portable: a splitmix64 hash of (seed, index, draw) feeds each random number,
// so copy `index` is the same whatever `count` is, on every standard library.
glm::mat4 scatter_placement(const Population& population, uint32_t index);

// Every copy, in index order: count entries (a family's kind: the copies it generated, shared
// with the population, not copied: a field of 200,000 cells holds them once).
std::shared_ptr<const std::vector<PopulationInstance>> generate_instances(const Population& population);

// The scene's populations whose kind is one of `kinds` (indices into scene.populations).
std::vector<size_t> populations_of_kinds(const std::vector<Population>& populations,
                                         const std::vector<std::string>& kinds);

}  // namespace canopy
