// The shadow-map math that the shaders run (../shaders/shadow_common.h), checked as C++.
#include "../shaders/shadow_common.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <initializer_list>

using namespace canopy::shader;

namespace {

// Depth along -z of the plane n.P = c seen through image-plane coordinates s (perspective).
float plane_depth(glm::vec3 n, float c, glm::vec2 s) { return c / glm::dot(n, glm::vec3(s, -1.0f)); }

}  // namespace

TEST_CASE("depth gradient matches finite differences of a tilted plane (perspective)") {
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
    const float c = -4.0f;  // plane in front of the light (depth > 0)
    const glm::vec2 s(0.2f, -0.1f);
    const float depth = plane_depth(n, c, s);
    REQUIRE(depth > 0.0f);
    const float texel_s = 1e-3f;  // image-plane size of one texel
    const glm::vec2 g = depth_gradient_per_texel(n, glm::vec3(s, -1.0f), texel_s * depth);
    const float du = plane_depth(n, c, s + glm::vec2(texel_s, 0.0f)) - depth;
    const float dv = plane_depth(n, c, s + glm::vec2(0.0f, texel_s)) - depth;
    CHECK(g.x == doctest::Approx(du).epsilon(0.01));
    CHECK(g.y == doctest::Approx(dv).epsilon(0.01));
    CHECK(depth_change_per_texel(g) == doctest::Approx(std::abs(du) + std::abs(dv)).epsilon(0.01));
}

TEST_CASE("depth gradient of an orthographic view is the plane's slope") {
    const glm::vec3 n = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));  // 45 degrees
    const glm::vec2 g = depth_gradient_per_texel(n, glm::vec3(0.0f, 0.0f, -1.0f), 0.5f);
    CHECK(g.x == doctest::Approx(0.5f));  // depth -z rises by one texel per texel at 45 degrees
    CHECK(g.y == doctest::Approx(0.0f));
}

TEST_CASE("a receiver facing the light head-on has no depth gradient") {
    const glm::vec2 g = depth_gradient_per_texel(glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f), 1.0f);
    CHECK(g.x == 0.0f);
    CHECK(g.y == 0.0f);
    CHECK(slope_scaled_bias(0.001f, 4.0f, depth_change_per_texel(g)) == doctest::Approx(0.001f));
}

TEST_CASE("grazing receivers keep the gradient and the bias finite") {
    for (float angle_degrees : {80.0f, 89.0f, 89.99f, 90.0f, 90.01f, 100.0f}) {
        const float a = glm::radians(angle_degrees);
        const glm::vec3 n(std::sin(a), 0.0f, std::cos(a));  // 90 degrees: edge-on to the light
        const glm::vec2 g = depth_gradient_per_texel(n, glm::vec3(0.0f, 0.0f, -1.0f), 1.0f);
        CAPTURE(angle_degrees);
        CHECK(std::isfinite(g.x));
        CHECK(std::isfinite(g.y));
        CHECK(std::abs(g.x) <= 1.0f / GRAZING_COS + 1e-3f);
        const float bias = slope_scaled_bias(0.0005f, 16.0f, depth_change_per_texel(g) * 1e-3f);
        CHECK(std::isfinite(bias));
        CHECK(bias >= 0.0005f);
    }
}

TEST_CASE("depth test and grid offsets") {
    CHECK(depth_test(0.5f, 0.5f) == 1.0f);   // equal depth counts as lit
    CHECK(depth_test(0.5f, 0.49f) == 0.0f);  // occluder nearer the light
    CHECK(depth_test(0.0f, 1.0f) == 1.0f);
    // A 3x3 grid is centred: offsets -1..1; a 4x4 grid -1.5..1.5.
    CHECK(grid_offset(0, 3) == glm::vec2(-1.0f, -1.0f));
    CHECK(grid_offset(4, 3) == glm::vec2(0.0f, 0.0f));
    CHECK(grid_offset(8, 3) == glm::vec2(1.0f, 1.0f));
    CHECK(grid_offset(0, 4) == glm::vec2(-1.5f, -1.5f));
    CHECK(grid_offset(15, 4) == glm::vec2(1.5f, 1.5f));
    CHECK(grid_offset(0, 1) == glm::vec2(0.0f, 0.0f));
}

TEST_CASE("nearest texel under uv, clamped at the edges") {
    CHECK(nearest_texel(glm::vec2(0.0f, 0.0f), glm::ivec2(4, 4)) == glm::ivec2(0, 0));
    CHECK(nearest_texel(glm::vec2(0.26f, 0.74f), glm::ivec2(4, 4)) == glm::ivec2(1, 2));
    CHECK(nearest_texel(glm::vec2(1.0f, 1.0f), glm::ivec2(4, 4)) == glm::ivec2(3, 3));    // u = 1 is the last texel
    CHECK(nearest_texel(glm::vec2(-0.5f, 2.0f), glm::ivec2(8, 2)) == glm::ivec2(0, 1));   // off the map: clamped
}

TEST_CASE("shadow-map coordinates from light clip space") {
    CHECK(shadow_uv(glm::vec4(0.0f, 0.0f, 0.5f, 1.0f)) == glm::vec2(0.5f, 0.5f));
    CHECK(shadow_uv(glm::vec4(-2.0f, 2.0f, 0.5f, 2.0f)) == glm::vec2(0.0f, 1.0f));
    CHECK(inside_shadow_map(glm::vec2(0.0f, 1.0f)));
    CHECK_FALSE(inside_shadow_map(glm::vec2(-0.01f, 0.5f)));
    CHECK(normalised_light_depth(3.0f, 1.0f, 0.25f) == doctest::Approx(0.5f));
}
