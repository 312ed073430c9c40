#include "density_thresholds.hpp"

#include "grass_random.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace canopy::grass {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

// Draw streams of one blade (item = blade index).
enum Draw : uint64_t { kUniform = 0, kGaussian = 16 };  // kGaussian + 2 k, + 2 k + 1: attempt k

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }  // Perlin's quintic

glm::vec2 lattice_gradient(int x, int z, uint32_t periods, uint64_t seed) {
    const auto wrap = [periods](int v) { return uint64_t((v % int(periods) + int(periods)) % int(periods)); };
    const float angle = kTwoPi * unit_random(seed, wrap(x) * periods + wrap(z), 0x6e6f697365ull);  // "noise"
    return {std::cos(angle), std::sin(angle)};
}

}  // namespace

float periodic_gradient_noise(glm::vec2 p, uint32_t periods, uint64_t seed) {
    const glm::vec2 q = p * float(periods);
    const glm::vec2 cell = glm::floor(q);
    const glm::vec2 f = q - cell;
    const int x = int(cell.x), z = int(cell.y);
    const auto corner = [&](int dx, int dz) {
        return glm::dot(lattice_gradient(x + dx, z + dz, periods, seed), f - glm::vec2(float(dx), float(dz)));
    };
    const float u = fade(f.x), v = fade(f.y);
    const float bottom = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * u;
    const float top = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * u;
    // Gradient noise in 2D lies within +-sqrt(2)/2; scaled to about [-1, 1].
    return std::sqrt(2.0f) * (bottom + (top - bottom) * v);
}

std::vector<float> equalised_ranks(std::span<const float> values) {
    std::vector<uint32_t> order(values.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return values[a] < values[b]; });
    std::vector<float> ranks(values.size());
    for (size_t r = 0; r < order.size(); ++r) ranks[order[r]] = float(double(r + 1) / double(values.size()));
    return ranks;
}

std::vector<float> density_thresholds(const ThresholdParams& params, std::span<const glm::vec3> roots, uint64_t seed) {
    std::vector<float> thresholds(roots.size());
    if (params.distribution == ThresholdDistribution::uniform) {
        for (size_t i = 0; i < roots.size(); ++i) thresholds[i] = unit_random_open_closed(seed, i, kUniform);
    } else {
        // Lemme §4.1.3: the raw noise clusters around its mean, so the map is histogram-equalised
        // (here over the roots it is sampled at: the ranks are exactly uniform over the blades).
        std::vector<float> noise(roots.size());
        for (size_t i = 0; i < roots.size(); ++i)
            noise[i] = periodic_gradient_noise({roots[i].x, roots[i].z}, params.noise_periods, seed);
        const std::vector<float> mean = equalised_ranks(noise);
        for (size_t i = 0; i < roots.size(); ++i) {
            thresholds[i] = mean[i];  // sigma = 0, or (with odds below 2^-64) no draw in range
            if (params.sigma <= 0.0f) continue;
            // eq 4.4-4.6: a Gaussian around the noise value restricted to ]0, 1], by rejection.
            for (uint64_t attempt = 0; attempt < 64; ++attempt) {
                const float u1 = unit_random_open_closed(seed, i, kGaussian + 2 * attempt);
                const float u2 = unit_random(seed, i, kGaussian + 2 * attempt + 1);
                const float normal = std::sqrt(-2.0f * std::log(u1)) * std::cos(kTwoPi * u2);  // Box-Muller
                const float t = mean[i] + params.sigma * normal;
                if (t > 0.0f && t <= 1.0f) {
                    thresholds[i] = t;
                    break;
                }
            }
        }
    }
    if (params.equalise) thresholds = equalised_ranks(thresholds);
    return thresholds;
}

}  // namespace canopy::grass
