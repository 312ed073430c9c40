#include "scene/population.hpp"

#include "scene/height_field.hpp"

#include "scene/population_kind.hpp"

#include "alpha_mask.h"

#include <algorithm>
#include <cmath>

namespace canopy {

float PopulationGround::height_at(glm::vec2 world_xz) const {
    if (!terrain) return 0.0f;
    return origin.y + terrain->at(world_xz - glm::vec2(origin.x, origin.z));
}

namespace {

// splitmix64's finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix, fixed here so that
// every platform draws the same numbers (std:: distributions differ between standard libraries).
uint64_t splitmix64(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// Random number `draw` of copy `index`, uniform in [0, 1) with 24 bits (exact in float).
double unit_random(uint64_t seed, uint32_t index, uint32_t draw) {
    const uint64_t bits = splitmix64(splitmix64(splitmix64(seed) ^ uint64_t(index)) + uint64_t(draw));
    return double(bits >> 40) * (1.0 / 16777216.0);
}

enum Draw : uint32_t { kDrawX, kDrawZ, kDrawYaw, kDrawScale };

float lerp(double from, double to, double t) { return float(from + (to - from) * t); }

}  // namespace

glm::mat4 scatter_placement(const Population& p, uint32_t index) {
    const float x = lerp(p.region_min.x, p.region_max.x, unit_random(p.seed, index, kDrawX));
    const float z = lerp(p.region_min.y, p.region_max.y, unit_random(p.seed, index, kDrawZ));
    const double yaw = p.random_yaw ? 2.0 * 3.14159265358979323846 * unit_random(p.seed, index, kDrawYaw) : 0.0;
    const float scale = lerp(p.scale_min, p.scale_max, unit_random(p.seed, index, kDrawScale));
    const float c = float(std::cos(yaw)), s = float(std::sin(yaw));
    // translate * rotate_y(yaw) * scale, written out (column-major): no library trigonometry in float.
    glm::mat4 m(0.0f);
    m[0] = glm::vec4(c * scale, 0.0f, -s * scale, 0.0f);
    m[1] = glm::vec4(0.0f, scale, 0.0f, 0.0f);
    m[2] = glm::vec4(s * scale, 0.0f, c * scale, 0.0f);
    m[3] = glm::vec4(x, p.ground_y, z, 1.0f);
    return m;
}

glm::vec4 AlphaMask::packed() const {
    const float k = kind == Kind::stripes ? shader::ALPHA_MASK_STRIPES : shader::ALPHA_MASK_NONE;
    return glm::vec4(k, float(axis), period, opaque);
}

std::shared_ptr<const std::vector<PopulationInstance>> generate_instances(const Population& population) {
    if (population.family)  // the family's own copies, kept alive with it
        return std::shared_ptr<const std::vector<PopulationInstance>>(population.family, &population.family->instances);
    const glm::mat4 own = population.prototype.instances.empty() ? glm::mat4(1.0f)
                                                                 : population.prototype.instances.front().matrix();
    std::vector<PopulationInstance> instances(population.count);
    for (uint32_t i = 0; i < population.count; ++i) {
        PopulationInstance& instance = instances[i];
        instance.model = scatter_placement(population, i) * own;
        // As GpuScene computes an object's DrawConstants::normal_matrix.
        const glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(instance.model)));
        for (int c = 0; c < 3; ++c) instance.normal_matrix[c] = glm::vec4(normal[c], 0.0f);
        instance.data = population.alpha_mask.packed();
    }
    return std::make_shared<const std::vector<PopulationInstance>>(std::move(instances));
}

std::vector<size_t> populations_of_kinds(const std::vector<Population>& populations,
                                         const std::vector<std::string>& kinds) {
    std::vector<size_t> chosen;
    for (size_t i = 0; i < populations.size(); ++i)
        if (std::find(kinds.begin(), kinds.end(), populations[i].kind) != kinds.end()) chosen.push_back(i);
    return chosen;
}

}  // namespace canopy
