// Boulanger's App. A interpolation of the slices' five baked light directions
// (shaders/btf_interpolation.h, the code grass.slices' shaders run): the weights are the
// spherical barycentric coordinates of eq A.1-A.2, equal to eq A.6's arccosine areas inside each
// quarter of the hemisphere, reach eq A.6's limits where it divides by zero (the sun at the
// zenith, on the horizon along an axis), sum to 1, stay in [0, 1] and finite for every direction,
// and change continuously from one quarter to the next. A baked row with weight 1 is Lambert's
// shading (eq 4.1) of the blade under that light.
#include "../shaders/btf_interpolation.h"
#include "shading.h"

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <vector>

using namespace canopy::shader;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::array<float, 5> weights(glm::vec3 l) {
    const BtfWeights w = btf_light_weights(l);
    return {w.w0123.x, w.w0123.y, w.w0123.z, w.w0123.w, w.w4};
}

// Eq A.3-A.6 for the spherical triangle (L, P, Q), P and Q two orthogonal unit axes: the angles
// at P, Q and L from the spherical law of cosines, in double precision, as the thesis writes them.
double paper_area(glm::dvec3 l, glm::dvec3 p, glm::dvec3 q) {
    const double at_p = std::acos(glm::dot(l, q) / glm::length(glm::cross(l, p)));
    const double at_q = std::acos(glm::dot(l, p) / glm::length(glm::cross(l, q)));
    const double at_l = std::acos(-glm::dot(l, p) * glm::dot(l, q) / (glm::length(glm::cross(l, p)) * glm::length(glm::cross(l, q))));
    return at_p + at_q + at_l - kPi;
}

// Eq A.2 with eq A.6's areas, for a light strictly inside its quarter: weights in row order.
std::array<double, 5> paper_weights(glm::dvec3 l) {
    const glm::dvec3 a(l.x >= 0 ? 1 : -1, 0, 0), b(0, 1, 0), c(0, 0, l.z >= 0 ? 1 : -1);
    const double wx = paper_area(l, b, c) / (kPi / 2), wy = paper_area(l, c, a) / (kPi / 2),
                 wz = paper_area(l, a, b) / (kPi / 2);
    return {wy, l.x >= 0 ? wx : 0.0, l.z >= 0 ? wz : 0.0, l.x >= 0 ? 0.0 : wx, l.z >= 0 ? 0.0 : wz};
}

glm::vec3 direction(double azimuth, double elevation) {
    return glm::vec3(float(std::cos(elevation) * std::cos(azimuth)), float(std::sin(elevation)),
                     float(std::cos(elevation) * std::sin(azimuth)));
}

}  // namespace

TEST_CASE("btf weights: inside every quarter of the hemisphere they are eq A.6's spherical areas over pi/2") {
    int compared = 0;
    for (int i = 0; i < 48; ++i)
        for (int j = 1; j < 12; ++j) {
            const double azimuth = 2.0 * kPi * (double(i) + 0.37) / 48.0, elevation = 0.5 * kPi * double(j) / 12.0;
            const glm::vec3 l = direction(azimuth, elevation);
            const std::array<float, 5> w = weights(l);
            const std::array<double, 5> paper = paper_weights(glm::dvec3(l));
            for (int row = 0; row < 5; ++row) {
                CAPTURE(azimuth);
                CAPTURE(elevation);
                CAPTURE(row);
                CHECK(w[row] == doctest::Approx(paper[row]).scale(1).epsilon(2e-5));
            }
            ++compared;
        }
    CHECK(compared == 48 * 11);
}

TEST_CASE("btf weights: a light along a baked direction weighs 1 on its row, where eq A.6 divides by zero") {
    for (int row = 0; row < BTF_LIGHTS; ++row) {
        const std::array<float, 5> w = weights(btf_light_direction(row));
        for (int other = 0; other < 5; ++other) CHECK(w[other] == doctest::Approx(other == row ? 1.0 : 0.0).epsilon(1e-6));
    }
    // Eq A.6 itself is 0/0 with the sun at the zenith: the limit is what the slices need.
    CHECK(std::isnan(paper_area(glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1))));  // A(LBC)
    // Approaching the zenith from any azimuth, the weights tend to (1, 0, 0, 0, 0).
    for (double azimuth : {0.1, 1.0, 2.5, 4.0, 5.9}) {
        const std::array<float, 5> near_zenith = weights(direction(azimuth, 0.5 * kPi - 1e-4));
        CHECK(near_zenith[0] > 0.9998f);
    }
}

TEST_CASE("btf weights: finite, in [0, 1], summing to 1 for every direction, below the horizon and zero included") {
    std::vector<glm::vec3> directions{glm::vec3(0.0f), glm::vec3(0, -1, 0), glm::vec3(1e-30f, 1, 0), glm::vec3(0, 1e-30f, 1),
                                      glm::vec3(1, -1e-7f, 1), glm::vec3(3e38f, 3e38f, 0), glm::vec3(-1e-38f, 1e-38f, 1e-38f)};
    for (int i = 0; i < 72; ++i)
        for (int j = -6; j <= 18; ++j) directions.push_back(direction(2.0 * kPi * i / 72.0, 0.5 * kPi * j / 18.0));
    for (const glm::vec3 l : directions) {
        const std::array<float, 5> w = weights(l);
        float sum = 0.0f;
        int non_zero = 0;
        for (float x : w) {
            REQUIRE(std::isfinite(x));
            CHECK(x >= 0.0f);
            CHECK(x <= 1.0f);
            sum += x;
            non_zero += x != 0.0f;
        }
        CAPTURE(l.x);
        CAPTURE(l.y);
        CAPTURE(l.z);
        CHECK(sum == doctest::Approx(1.0).epsilon(1e-6));
        CHECK(non_zero <= 3);
    }
    // Below the horizon, the light is taken at the horizon: the Y+ row weighs nothing.
    CHECK(weights(glm::vec3(1, -0.5f, 1))[0] == doctest::Approx(0.0).scale(1).epsilon(1e-6));
    CHECK(weights(glm::vec3(1, -0.5f, 1))[1] == doctest::Approx(weights(glm::vec3(1, 0, 1))[1]));
}

TEST_CASE("btf weights: continuous across the quarters' borders") {
    for (double elevation : {0.0, 0.3, 1.0, 1.5}) {
        for (double border : {0.0, 0.5 * kPi, kPi, 1.5 * kPi}) {
            const std::array<float, 5> before = weights(direction(border - 1e-4, elevation));
            const std::array<float, 5> after = weights(direction(border + 1e-4, elevation));
            for (int row = 0; row < 5; ++row) {
                CAPTURE(elevation);
                CAPTURE(border);
                CAPTURE(row);
                CHECK(std::abs(before[row] - after[row]) < 1e-3f);
            }
        }
    }
}

TEST_CASE("btf rows: weight 1 on a baked row is eq 4.1's shading of the blade under that light") {
    const glm::vec3 albedo(0.2f, 0.7f, 0.1f), ambient(0.15f), irradiance(3.0f, 2.5f, 2.0f);
    for (float gamma : {0.0f, 0.6f})
        for (const glm::vec3 n : {glm::normalize(glm::vec3(0.3f, 0.5f, -0.8f)), glm::vec3(0, 1, 0), glm::vec3(-1, 0, 0)})
            for (int row = 0; row < BTF_LIGHTS; ++row) {
                const glm::vec3 l = btf_light_direction(row);
                const float c = glm::dot(n, l);
                const glm::vec3 direct = irradiance * (std::max(c, 0.0f) + gamma * std::max(-c, 0.0f));
                const glm::vec3 expected = lambert_radiance(albedo, direct, 1.0f, ambient);
                const glm::vec3 got = btf_radiance(albedo, btf_baked_row(albedo, n, row, gamma), irradiance, ambient);
                for (int k = 0; k < 3; ++k) CHECK(got[k] == doctest::Approx(expected[k]).epsilon(1e-6));
            }
}
