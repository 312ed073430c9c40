// The blade outline (shaders/blade_alpha.h): the hard test, the smooth alpha for
// alpha-to-coverage agreeing with it, the covered fraction, and the extremes.
#include "../shaders/blade_alpha.h"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

namespace shader = canopy::shader;

TEST_CASE("blade outline: full width at the root, a point at the tip, narrowing all the way") {
    for (float taper : {0.25f, 1.0f, 2.0f, 8.0f}) {
        CAPTURE(taper);
        CHECK(shader::blade_half_width(0.0f, taper) == 0.5f);
        CHECK(shader::blade_half_width(1.0f, taper) == 0.0f);
        float previous = 0.5f;
        for (int i = 1; i <= 100; ++i) {
            const float w = shader::blade_half_width(float(i) / 100.0f, taper);
            REQUIRE(w <= previous);
            previous = w;
        }
        // Outside [0, 1] the outline clamps rather than growing or going NaN.
        CHECK(shader::blade_half_width(-0.5f, taper) == 0.5f);
        CHECK(shader::blade_half_width(1.5f, taper) == 0.0f);
    }
    // A larger taper exponent keeps the blade wide for longer.
    CHECK(shader::blade_half_width(0.5f, 4.0f) > shader::blade_half_width(0.5f, 1.0f));
}

TEST_CASE("blade outline: the smooth alpha is >= 0.5 exactly where the hard test is opaque, symmetric in u") {
    for (float fw : {0.0f, 0.01f, 0.2f})
        for (int j = 0; j <= 64; ++j)
            for (int i = 0; i <= 64; ++i) {
                const glm::vec2 uv{float(i) / 64.0f, float(j) / 64.0f};
                CAPTURE(fw);
                CAPTURE(uv.x);
                CAPTURE(uv.y);
                const float a = shader::blade_alpha(uv, 2.0f, fw);
                CAPTURE(a);
                REQUIRE(std::isfinite(a));
                REQUIRE(a >= 0.0f);
                REQUIRE(a <= 1.0f);
                REQUIRE(a == doctest::Approx(shader::blade_alpha({1.0f - uv.x, uv.y}, 2.0f, fw)).epsilon(1e-5));
                // Where the footprint lies inside the strip and fits in the outline's width,
                // alpha >= 0.5 is the hard test.
                // (On the edge itself the box filter gives 0.5 up to rounding.)
                const float w = shader::blade_half_width(uv.y, 2.0f);
                if (uv.x - 0.5f * fw >= 0.0f && uv.x + 0.5f * fw <= 1.0f && 2.0f * w >= fw &&
                    std::abs(std::abs(uv.x - 0.5f) - w) > 1e-6f)
                    REQUIRE((a >= 0.5f) == shader::blade_opaque(uv, 2.0f));
            }
    // A wider filter softens: half a filter width inside the edge is fully opaque.
    const float edge = 0.5f - shader::blade_half_width(0.5f, 2.0f);
    CHECK(shader::blade_alpha({edge + 0.05f, 0.5f}, 2.0f, 0.1f) == doctest::Approx(1.0f));
    CHECK(shader::blade_alpha({edge - 0.05f, 0.5f}, 2.0f, 0.1f) == doctest::Approx(0.0f));
    CHECK(shader::blade_alpha({edge, 0.5f}, 2.0f, 0.1f) == doctest::Approx(0.5f));
}

TEST_CASE("blade outline: on a strip narrower than a pixel the alpha is the outline's share of its width") {
    // Far blades are thinner than a pixel: the samples the strip covers must carry the outline's
    // coverage (2 w(v)), or alpha-to-coverage thins or thickens the far field.
    for (float fw : {1.0f, 3.0f, 1e6f, INFINITY})
        for (float taper : {0.5f, 2.0f, 8.0f})
            for (int j = 0; j <= 16; ++j) {
                const float v = float(j) / 16.0f;
                for (float u : {0.0f, 0.2f, 0.5f, 0.9f, 1.0f})
                    CHECK(shader::blade_alpha({u, v}, taper, fw) ==
                          doctest::Approx(2.0f * shader::blade_half_width(v, taper)).epsilon(1e-5));
            }
    // The mean alpha over the strip is the covered fraction (at v = 0.5) for a footprint well
    // under the strip's width; sliding the footprint inside the strip over-covers a strip about
    // a pixel wide (f = 0.8: 0.855 for 0.75, measured), the price of exactness at f >= 1.
    const auto mean_alpha = [](float fw) {
        double sum = 0.0;
        constexpr int n = 4000;
        for (int i = 0; i < n; ++i) sum += shader::blade_alpha({(float(i) + 0.5f) / n, 0.5f}, 2.0f, fw);
        return sum / n;
    };
    const double covered = 2.0 * shader::blade_half_width(0.5f, 2.0f);
    CHECK(mean_alpha(0.05f) == doctest::Approx(covered).epsilon(0.01));
    CHECK(mean_alpha(0.3f) == doctest::Approx(covered).epsilon(0.05));
    CHECK(mean_alpha(0.8f) == doctest::Approx(covered).epsilon(0.15));
    // Extremes: a zero, negative or NaN width is the hard test; never NaN.
    for (float fw : {0.0f, -1.0f, std::nanf("")}) {
        CHECK(shader::blade_alpha({0.5f, 0.5f}, 2.0f, fw) == 1.0f);
        CHECK(shader::blade_alpha({0.0f, 0.9f}, 2.0f, fw) == 0.0f);
    }
}

TEST_CASE("blade outline: it covers taper / (taper + 1) of the strip") {
    for (float taper : {0.5f, 1.0f, 3.0f}) {
        int opaque = 0;
        constexpr int n = 400;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                opaque += shader::blade_opaque({(float(i) + 0.5f) / n, (float(j) + 0.5f) / n}, taper);
        CHECK(double(opaque) / (n * n) == doctest::Approx(shader::blade_coverage(taper)).epsilon(0.01));
    }
}
