#include "blade_patch.hpp"

#include "../shaders/blade_curve.h"
#include "grass_random.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace canopy::grass {

namespace {

constexpr float kPi = 3.14159265358979323846f;

// Draw streams of one blade (item = blade index); the thresholds use their own seed.
enum Draw : uint64_t { kRootX, kRootZ, kHeight, kTilt, kAzimuth, kBend, kWidth, kColour, kVertexColour = 64 };

float between(float lo, float hi, float u) { return lo + (hi - lo) * u; }

void check_range(const char* name, float lo, float hi, float min, float max) {
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo >= min && hi <= max && lo <= hi))
        throw std::invalid_argument(fmt::format("grass patch: {} range [{}, {}] must lie within [{}, {}], min <= max",
                                                name, lo, hi, min, max));
}

glm::vec3 root_of(const BladePatchParams& p, uint32_t i, glm::uvec2 grid) {
    const float u = unit_random(p.seed, i, kRootX), v = unit_random(p.seed, i, kRootZ);
    if (p.roots == RootPlacement::uniform) return {u, 0.0f, v};
    // One root in each grid cell, jittered inside it (Boulanger L841).
    const uint32_t column = i % grid.x, row = i / grid.x;
    return {(float(column) + u) / float(grid.x), 0.0f, (float(row) + v) / float(grid.y)};
}

}  // namespace

glm::uvec2 stratified_grid(uint32_t blades) {
    uint32_t columns = uint32_t(std::sqrt(double(blades)));
    while (columns > 1 && blades % columns != 0) --columns;
    columns = std::max(columns, 1u);
    return {columns, blades / columns};
}

void validate(const BladePatchParams& p) {
    if (p.blades == 0 || p.blades > (1u << 20))
        throw std::invalid_argument(fmt::format("grass patch: blades = {} must be in [1, {}]", p.blades, 1u << 20));
    if (p.subdivisions > 64)
        throw std::invalid_argument(fmt::format("grass patch: subdivisions = {} must be in [0, 64]", p.subdivisions));
    check_range("height", p.height_min, p.height_max, 1e-4f, 10.0f);
    check_range("tilt (degrees)", p.tilt_min_degrees, p.tilt_max_degrees, 0.0f, 80.0f);
    check_range("bend", p.bend_min, p.bend_max, 0.0f, 1.0f);
    check_range("width", p.width_min, p.width_max, 1e-5f, 1.0f);
    check_range("blade colour variation", 0.0f, p.blade_colour_variation, 0.0f, 1.0f);
    check_range("vertex colour variation", 0.0f, p.vertex_colour_variation, 0.0f, 1.0f);
    if (p.thresholds.distribution == ThresholdDistribution::clustered &&
        !(p.thresholds.sigma >= 0.0f && p.thresholds.sigma <= 10.0f && p.thresholds.noise_periods >= 1 &&
          p.thresholds.noise_periods <= 256))
        throw std::invalid_argument(fmt::format("grass patch: clustered thresholds need sigma in [0, 10] and "
                                                "noise_periods in [1, 256] (sigma = {}, noise_periods = {})",
                                                p.thresholds.sigma, p.thresholds.noise_periods));
}

BladePatch generate_blade_patch(const BladePatchParams& p) {
    validate(p);
    BladePatch patch;
    patch.params = p;
    const glm::uvec2 grid = stratified_grid(p.blades);
    std::vector<glm::vec3> roots(p.blades);
    for (uint32_t i = 0; i < p.blades; ++i) roots[i] = root_of(p, i, grid);
    const std::vector<float> thresholds = density_thresholds(p.thresholds, roots, random_key(p.seed, 0x7468ull));

    const uint32_t segments = segments_per_blade(p.subdivisions);
    patch.blades.reserve(p.blades);
    patch.vertices.reserve(size_t(p.blades) * vertices_per_blade(p.subdivisions));
    patch.indices.reserve(size_t(p.blades) * 6 * segments);
    for (uint32_t i = 0; i < p.blades; ++i) {
        Blade blade;
        blade.root = roots[i];
        const float tip_height = between(p.height_min, p.height_max, unit_random(p.seed, i, kHeight));
        const float tilt = between(p.tilt_min_degrees, p.tilt_max_degrees, unit_random(p.seed, i, kTilt)) * kPi / 180.0f;
        const float azimuth = 2.0f * kPi * unit_random(p.seed, i, kAzimuth);
        const float bend = between(p.bend_min, p.bend_max, unit_random(p.seed, i, kBend));
        // Launch direction: `tilt` from the vertical towards `azimuth`. With the pull a fraction
        // `bend` of the largest allowed (rise / 2), the tip's height is rise (1 - bend / 2).
        const glm::vec3 direction{std::sin(tilt) * std::cos(azimuth), std::cos(tilt), std::sin(tilt) * std::sin(azimuth)};
        const float rise = tip_height / (1.0f - 0.5f * bend);
        const float speed = rise / direction.y;
        blade.launch = direction * speed;
        blade.gravity = {0.0f, -bend * shader::blade_max_pull(rise), 0.0f};
        blade.across = {-std::sin(azimuth), 0.0f, std::cos(azimuth)};
        blade.width = between(p.width_min, p.width_max, unit_random(p.seed, i, kWidth));
        blade.threshold = thresholds[i];
        blade.colour = 1.0f - p.blade_colour_variation * unit_random(p.seed, i, kColour);

        const uint32_t first = uint32_t(patch.vertices.size());
        for (uint32_t s = 0; s <= segments; ++s) {
            const float t = float(s) / float(segments);
            const glm::vec3 spine = blade.root + shader::blade_point(blade.launch, blade.gravity, t);
            const glm::vec3 tangent = shader::blade_tangent(blade.launch, blade.gravity, t);
            const glm::vec3 normal = glm::normalize(glm::cross(tangent, blade.across));
            patch.tallest = std::max(patch.tallest, spine.y);
            for (uint32_t side = 0; side < 2; ++side) {
                BladeVertex v;
                v.position = spine + blade.across * (blade.width * (float(side) - 0.5f));
                v.normal = normal;
                v.uv = {float(side), t};
                v.root = blade.root;
                v.threshold = blade.threshold;
                v.colour = blade.colour *
                           (1.0f - p.vertex_colour_variation * unit_random(p.seed, i, kVertexColour + 2 * s + side));
                patch.vertices.push_back(v);
            }
        }
        for (uint32_t s = 0; s < segments; ++s) {
            const uint32_t a = first + 2 * s;  // left and right at s, then at s + 1
            for (uint32_t index : {a, a + 1, a + 2, a + 2, a + 1, a + 3}) patch.indices.push_back(index);
        }
        patch.blades.push_back(blade);
    }
    return patch;
}

}  // namespace canopy::grass
