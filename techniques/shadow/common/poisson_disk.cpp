#include "poisson_disk.hpp"

#include <cmath>
#include <limits>
#include <random>

namespace canopy {

std::vector<std::array<float, 2>> poisson_disk(int count, uint32_t seed) {
    constexpr int kCandidatesPerPoint = 32;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
    auto random_in_disk = [&] {
        for (;;) {
            float x = uniform(rng), y = uniform(rng);
            if (x * x + y * y <= 1.0f) return std::array<float, 2>{x, y};
        }
    };
    std::vector<std::array<float, 2>> points;
    points.reserve(size_t(std::max(count, 0)));
    for (int i = 0; i < count; ++i) {
        std::array<float, 2> best{};
        float best_distance = -1.0f;
        for (int c = 0; c < kCandidatesPerPoint; ++c) {
            auto candidate = random_in_disk();
            float nearest = std::numeric_limits<float>::max();
            for (const auto& p : points) {
                float dx = p[0] - candidate[0], dy = p[1] - candidate[1];
                nearest = std::min(nearest, dx * dx + dy * dy);
            }
            if (nearest > best_distance) {
                best_distance = nearest;
                best = candidate;
            }
        }
        points.push_back(best);
    }
    return points;
}

}  // namespace canopy
