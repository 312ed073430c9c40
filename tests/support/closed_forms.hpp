// Closed forms the reference is checked against, shared by its tests.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace canopy::test {

// Lambert's formula for a uniform polygonal emitter of radiance `radiance` fully above the
// receiver's horizon: E = L/2 * |sum_i angle(u_i, u_i+1) * n . normalize(u_i x u_i+1)|, u_i the
// unit vectors from p to the corners.
inline double polygon_irradiance(const std::vector<glm::dvec3>& corners, glm::dvec3 p, glm::dvec3 n, double radiance) {
    double sum = 0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 a = glm::normalize(corners[i] - p);
        const glm::dvec3 b = glm::normalize(corners[(i + 1) % corners.size()] - p);
        sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return 0.5 * radiance * std::abs(sum);
}

}  // namespace canopy::test
