// The transition functions grass.lod will draw with (shaders/lod_selection.h): Boulanger's
// weights (eq 4.3-4.5), Algorithm 1 and eq 4.6 with canopy's centred window, Lemme's eq 5.25
// made complementary and eq 5.26 guarded. Over all thresholds, densities and weights: every blade
// the density keeps is drawn exactly once in total (opacities summing to 1), none that it thins;
// a representation drawn alone (w = 0 or 1) leaves no blade semi-transparent; nothing is NaN.
#include "../shaders/lod_selection.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

namespace shader = canopy::shader;

namespace {

// Thresholds as the patch draws them: in ]0, 1], both ends included (1 - k / 2^24).
std::vector<float> thresholds() {
    std::vector<float> t{1.0f / 16777216.0f, 1.0f};
    for (int i = 1; i < 4096; ++i) t.push_back(float(i) / 4096.0f);
    return t;
}

const std::vector<float> kDensities{0.0f, 0.005f, 0.01f, 0.3f, 0.77f, 1.0f};

}  // namespace

TEST_CASE("lod weights: eq 4.3-4.5 at their ends and in between, w_hs = 1 - w_g") {
    const float min_geom = 10.0f, max_geom = 20.0f, min_btf = 40.0f, max_btf = 80.0f;
    CHECK(shader::lod_weight_geometry(0.0f, min_geom, max_geom) == 1.0f);
    CHECK(shader::lod_weight_geometry(10.0f, min_geom, max_geom) == 1.0f);
    CHECK(shader::lod_weight_geometry(15.0f, min_geom, max_geom) == doctest::Approx(0.5f));
    CHECK(shader::lod_weight_geometry(20.0f, min_geom, max_geom) == 0.0f);
    CHECK(shader::lod_weight_geometry(1e30f, min_geom, max_geom) == 0.0f);
    for (float d = 0.0f; d <= 100.0f; d += 0.25f) {
        CAPTURE(d);
        const float wg = shader::lod_weight_geometry(d, min_geom, max_geom);
        const float wvs = shader::lod_weight_vertical_slices(d, min_geom, max_geom, min_btf, max_btf);
        const float whs = shader::lod_weight_horizontal_slice(d, min_geom, max_geom);
        CHECK(whs == doctest::Approx(1.0f - wg));
        CHECK(wvs >= 0.0f);
        CHECK(wvs <= 1.0f);
        if (d <= max_geom) CHECK(wvs == doctest::Approx(1.0f - wg));  // "w_vs(d) = 1 - w_g(d) for d <= maxGeom"
        if (d >= max_geom && d <= min_btf) CHECK(wvs == 1.0f);
        if (d >= max_btf) CHECK(wvs == 0.0f);
    }
    CHECK(shader::lod_weight_vertical_slices(60.0f, min_geom, max_geom, min_btf, max_btf) == doctest::Approx(0.5f));
}

TEST_CASE("lod selection: every blade the density keeps is drawn once in total, near and far, at any weight") {
    const std::vector<float> t = thresholds();
    for (float ld : kDensities)
        for (int k = 0; k <= 64; ++k) {
            const float w = float(k) / 64.0f;
            CAPTURE(ld);
            CAPTURE(w);
            int kept = 0, semi = 0, wrong = 0;
            double far_share = 0.0;
            for (float dth : t) {
                const float far = shader::lod_far_opacity(dth, ld, w), near = shader::lod_near_opacity(dth, ld, w);
                if (!(std::isfinite(far) && std::isfinite(near) && far >= 0.0f && far <= 1.0f && near >= 0.0f &&
                      near <= 1.0f))
                    ++wrong;
                const bool drawn = ld >= shader::LOD_MIN_DENSITY && dth <= ld;
                if (drawn) {
                    ++kept;
                    far_share += far;
                    wrong += std::abs(far + near - 1.0f) > 1e-6f;
                    semi += far > 0.0f && far < 1.0f;
                } else {
                    wrong += far != 0.0f || near != 0.0f;
                }
                if (drawn && k == 0) wrong += far != 0.0f || near != 1.0f;   // the near one alone: all opaque
                if (drawn && k == 64) wrong += far != 1.0f || near != 0.0f;  // the far one alone
            }
            CHECK(wrong == 0);
            if (kept == 0) continue;
            // Few blades are semi-transparent at once: at most the window, 2 omega of the density.
            CHECK(double(semi) <= (2.0 * shader::lod_window(w) + 2.0 / 4096.0) * kept / ld + 1.0);
            // The far representation takes the share of the blades the weight says, to the window's width.
            CHECK(std::abs(far_share / kept - w) <= 2.0 * shader::LOD_OMEGA_MAX + 2.0 / kept);
        }
}

TEST_CASE("lod selection: the window is widest mid-band and never zero (Algorithm 1's omega_0)") {
    CHECK(shader::lod_window(0.5f) == doctest::Approx(shader::LOD_OMEGA_MAX));
    CHECK(shader::lod_window(0.0f) == doctest::Approx(shader::LOD_OMEGA_MAX * shader::LOD_OMEGA_0));
    CHECK(shader::lod_window(1.0f) == doctest::Approx(shader::LOD_OMEGA_MAX * shader::LOD_OMEGA_0));
    CHECK(shader::lod_window(-3.0f) == shader::lod_window(0.0f));  // clamped
    CHECK(shader::lod_window(7.0f) == shader::lod_window(1.0f));
}

TEST_CASE("lod selection: Lemme's eq 5.25, made complementary, puts every kept blade in exactly one representation") {
    const std::vector<float> t = thresholds();
    int naive_twice = 0, naive_dropped = 0;
    for (float ld : kDensities)
        for (int k = 0; k <= 64; ++k) {
            const float w1 = float(k) / 64.0f, w2 = 1.0f - w1;
            for (float bdth : t) {
                const bool first = shader::lod_in_first(bdth, ld, w1), second = shader::lod_in_second(bdth, ld, w1);
                const bool kept = bdth <= ld;
                REQUIRE(int(first) + int(second) == (kept ? 1 : 0));
                // The paper's test for both (bdth <= w ld with w2 = 1 - w1) draws some twice, drops others.
                const bool naive_first = bdth <= w1 * ld, naive_second = bdth <= w2 * ld;
                naive_twice += naive_first && naive_second;
                naive_dropped += kept && !naive_first && !naive_second;
                // Eq 5.26 and its complement: a kept blade's opacities sum to 1; finite where ld = 0.
                const float a = shader::lod_first_opacity_smooth(bdth, ld, w1, 0.02f);
                const float b = shader::lod_second_opacity_smooth(bdth, ld, w1, 0.02f);
                REQUIRE(std::isfinite(a));
                REQUIRE(std::isfinite(b));
                REQUIRE((kept && ld > 0.0f ? std::abs(a + b - 1.0f) <= 1e-6f : (a == 0.0f && b == 0.0f)));
            }
        }
    CHECK(naive_twice > 1000);
    CHECK(naive_dropped > 1000);
}
