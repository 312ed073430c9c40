#include "support/cpu_checks.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace canopy::grass::test {

float max_difference(const Image& a, const Image& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    float m = 0.0f;
    for (size_t i = 0; i < a.pixels.size(); ++i) m = std::max(m, std::abs(a.pixels[i] - b.pixels[i]));
    return m;
}

bool corners_may_be_seen(const glm::mat4& view_proj, const std::array<glm::vec3, 8>& corners) {
    int outside[6] = {0, 0, 0, 0, 0, 0};
    for (const glm::vec3& corner : corners) {
        const glm::vec4 clip = view_proj * glm::vec4(corner, 1.0f);
        outside[0] += clip.x < -clip.w;
        outside[1] += clip.x > clip.w;
        outside[2] += clip.y < -clip.w;
        outside[3] += clip.y > clip.w;
        outside[4] += clip.z < 0.0f;
        outside[5] += clip.z > clip.w;
    }
    return std::none_of(std::begin(outside), std::end(outside), [](int n) { return n == 8; });
}

}  // namespace canopy::grass::test
