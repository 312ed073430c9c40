// canopy's shading model that the shaders and the reference run (harness/shaders/shading.h),
// checked as C++.
#include "shading.h"

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include <cmath>

using namespace canopy::shader;

TEST_CASE("Lambert shading with ambient") {
    const glm::vec3 albedo(0.5f);
    const glm::vec3 radiance = lambert_radiance(albedo, glm::vec3(PI), 1.0f, glm::vec3(0.1f));
    CHECK(radiance.x == doctest::Approx(0.5f * (1.0f + 0.1f)));
    const glm::vec3 shadowed = lambert_radiance(albedo, glm::vec3(PI), 0.0f, glm::vec3(0.1f));
    CHECK(shadowed.x == doctest::Approx(0.05f));  // only ambient in umbra
}

TEST_CASE("point-like light irradiance: inverse square, receiver and emitter cosines") {
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    const glm::vec3 I(8.0f);
    const float cos_half = std::cos(glm::radians(30.0f));
    // Sphere light 2 m straight above: E = I / d^2.
    CHECK(point_irradiance(LIGHT_SPHERE, glm::vec3(0.0f), n, glm::vec3(0, 2, 0), down, I, cos_half).x == doctest::Approx(2.0f));
    // Rect light, receiver 45 degrees off its axis: both cosines apply; d^2 = 8.
    const glm::vec3 p(2.0f, 0.0f, 0.0f);
    const float c45 = std::sqrt(0.5f);
    CHECK(point_irradiance(LIGHT_RECT, p, n, glm::vec3(0, 2, 0), down, I, cos_half).x == doctest::Approx(8.0f * c45 * c45 / 8.0f));
    // Behind a one-sided rect light: nothing.
    CHECK(point_irradiance(LIGHT_RECT, glm::vec3(0, 4, 0), down, glm::vec3(0, 2, 0), down, I, cos_half).x == 0.0f);
    // Light on the far side of the receiver: nothing, never negative.
    CHECK(point_irradiance(LIGHT_SPHERE, glm::vec3(0.0f), n, glm::vec3(0, -2, 0), down, I, cos_half).x == 0.0f);
    // Coincident light and receiver stays finite.
    CHECK(std::isfinite(point_irradiance(LIGHT_SPHERE, glm::vec3(0.0f), n, glm::vec3(0.0f), down, I, cos_half).x));
}

TEST_CASE("spot cone falloff is 1 inside, 0 outside, monotone between") {
    const float cos_half = std::cos(glm::radians(30.0f));
    CHECK(spot_falloff(1.0f, cos_half) == 1.0f);
    CHECK(spot_falloff(std::cos(glm::radians(26.0f)), cos_half) == 1.0f);  // inside 90% of the half-angle
    CHECK(spot_falloff(std::cos(glm::radians(31.0f)), cos_half) == 0.0f);
    float previous = 1.0f;
    for (float deg = 26.0f; deg <= 30.0f; deg += 0.25f) {
        const float f = spot_falloff(std::cos(glm::radians(deg)), cos_half);
        CHECK(f <= previous + 1e-6f);
        CHECK(f >= 0.0f);
        previous = f;
    }
}

TEST_CASE("directional irradiance") {
    const glm::vec3 E(3.0f);
    CHECK(directional_irradiance(glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), E).x == doctest::Approx(3.0f));
    CHECK(directional_irradiance(glm::vec3(0, -1, 0), glm::vec3(0, -1, 0), E).x == 0.0f);
    const glm::vec3 tilted = glm::normalize(glm::vec3(1, -1, 0));
    CHECK(directional_irradiance(glm::vec3(0, 1, 0), tilted, E).x == doctest::Approx(3.0f * std::sqrt(0.5f)));
}
