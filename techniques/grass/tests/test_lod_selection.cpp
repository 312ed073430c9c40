// The transition functions grass.lod will draw with (shaders/lod_selection.h): Boulanger's
// weights (eq 4.3-4.5), Algorithm 1 and eq 4.6 with canopy's centred window, Lemme's eq 5.25
// made complementary and eq 5.26 guarded. Over all thresholds, densities and weights: every blade
// the density keeps is drawn exactly once in total (opacities summing to 1), none that it thins;
// a representation drawn alone (w = 0 or 1) leaves no blade semi-transparent; nothing is NaN.
// grass.lod's three bands (lod_cuts, lod_band, grass_blade_in_band): over distances through both
// transitions, every blade the density keeps falls in exactly one band, none it thins in any.
#include "../shaders/blade_texels.h"
#include "../shaders/grass_density.h"
#include "../shaders/lod_selection.h"

#include <doctest/doctest.h>

#include <algorithm>
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

TEST_CASE("grass.lod's bands: over every distance, threshold and density, each kept blade falls in exactly one band") {
    struct Bands {
        float geometry_full, geometry_none, image_start, image_full;
    };
    // Separate transitions, touching ones, overlapping ends and steps (equal ends: no ramp).
    const std::vector<Bands> settings{{5, 20, 50, 80}, {5, 20, 20, 40}, {10, 10, 30, 30}, {0, 0, 0, 0}, {1e6f, 1e6f, 1e6f, 1e6f}};
    for (const Bands& b : settings) {
        CAPTURE(b.geometry_full);
        CAPTURE(b.image_start);
        for (float d = 0.0f; d <= 120.0f; d += 0.37f) {
            const shader::vec2 cuts = shader::lod_cuts(d, b.geometry_full, b.geometry_none, b.image_start, b.image_full);
            REQUIRE(cuts.x >= 0.0f);
            REQUIRE(cuts.x <= cuts.y);
            REQUIRE(cuts.y <= 1.0f);
            for (float ld : kDensities)
                for (float th : thresholds()) {
                    int drawn = 0;
                    for (int r : {shader::GRASS_LOD_GEOMETRY, shader::GRASS_LOD_VOLUME, shader::GRASS_LOD_IMAGE})
                        drawn += shader::grass_blade_in_band(th, ld, shader::lod_band(r, cuts)) ? 1 : 0;
                    if (drawn != (th <= ld ? 1 : 0)) {
                        CAPTURE(d);
                        CAPTURE(ld);
                        CAPTURE(th);
                        REQUIRE(drawn == (th <= ld ? 1 : 0));
                    }
                }
        }
    }
}

TEST_CASE("grass.lod's bands: all blades near, all volume between the transitions, all image far; w_vs between") {
    const float gf = 5.0f, gn = 20.0f, is = 50.0f, ifull = 80.0f;
    const auto cuts = [&](float d) { return shader::lod_cuts(d, gf, gn, is, ifull); };
    CHECK(cuts(0.0f).x == 1.0f);
    CHECK(cuts(gf).x == 1.0f);
    CHECK(cuts(gn).x == 0.0f);
    CHECK(cuts(gn).y == 1.0f);
    CHECK(cuts(is).y == 1.0f);
    CHECK(cuts(ifull).y == 0.0f);
    CHECK(cuts(1000.0f).y == 0.0f);
    for (float d = 0.0f; d < 100.0f; d += 0.5f) {
        CAPTURE(d);
        // c1 is eq 4.3's w_g, c2 - c1 eq 4.4's w_vs (the transitions do not overlap here).
        CHECK(cuts(d).x == doctest::Approx(shader::lod_weight_geometry(d, gf, gn)).epsilon(1e-6));
        CHECK(cuts(d).y - cuts(d).x == doctest::Approx(shader::lod_weight_vertical_slices(d, gf, gn, is, ifull)).epsilon(1e-5));
        // Farther cells keep fewer blades near and more far.
        CHECK(cuts(d + 0.5f).x <= cuts(d).x);
        CHECK(cuts(d + 0.5f).y <= cuts(d).y);
    }
    // Equal ends are a step, not 0 / 0.
    CHECK(shader::lod_ramp_down(9.9f, 10.0f, 10.0f) == 1.0f);
    CHECK(shader::lod_ramp_down(10.0f, 10.0f, 10.0f) == 0.0f);
    // The band (0, 1] is grass_blade_drawn.
    for (float ld : kDensities)
        for (float th : thresholds())
            REQUIRE(shader::grass_blade_in_band(th, ld, shader::vec2(0.0f, 1.0f)) == shader::grass_blade_drawn(th, ld));
}

TEST_CASE("grass.lod's bands: outside its cull distances a representation's band is empty (the cull drops nothing drawn)") {
    struct Bands {
        float geometry_full, geometry_none, image_start, image_full;
    };
    const std::vector<Bands> settings{{5, 20, 50, 80}, {5, 20, 20, 40}, {10, 10, 30, 30}, {0, 0, 0, 0}, {2, 2.5f, 3, 4}};
    for (const Bands& b : settings)
        for (int r : {shader::GRASS_LOD_GEOMETRY, shader::GRASS_LOD_VOLUME, shader::GRASS_LOD_IMAGE}) {
            CAPTURE(b.geometry_full);
            CAPTURE(b.image_start);
            CAPTURE(r);
            const shader::vec2 range =
                shader::lod_band_distances(r, b.geometry_full, b.geometry_none, b.image_start, b.image_full);
            REQUIRE(range.x <= range.y);
            int inside_nonempty = 0;
            for (float d = 0.0f; d <= 120.0f; d += 0.01f) {
                const shader::vec2 band =
                    shader::lod_band(r, shader::lod_cuts(d, b.geometry_full, b.geometry_none, b.image_start, b.image_full));
                const bool empty = !(band.y > band.x);
                if (d < range.x || d > range.y) {
                    if (!empty) {
                        CAPTURE(d);
                        REQUIRE(empty);
                    }
                } else {
                    inside_nonempty += empty ? 0 : 1;
                }
            }
            // The ranges are not wider than they need be: where one has room, its band is drawn there.
            if (range.y > range.x + 0.1f && range.x < 119.0f) CHECK(inside_nonempty > 0);
        }
}

TEST_CASE("grass.lod's volume levels (Lemme's 8, 2, 1 slices): each kept blade falls in exactly one of the five bands, "
          "one level is the volume's band, and outside its cull distances a level's band is empty") {
    struct Levels {
        float gf, gn, v2s, v2f, v3s, v3f, is, ifull;
    };
    // Lemme's football field (L930-935), touching ramps, steps, everything at 0, and levels at the ends.
    const std::vector<Levels> settings{{5, 20, 50, 80, 100, 160, 200, 300}, {5, 20, 20, 40, 40, 60, 60, 80},
                                       {10, 10, 30, 30, 50, 50, 70, 70},     {0, 0, 0, 0, 0, 0, 0, 0},
                                       {0, 0, 0, 0, 1e6f, 1e6f, 1e6f, 1e6f}};
    // Every 16th threshold of the patch's (the cuts are continuous: this finds a gap or an overlap of
    // more than 1/256) keeps the sanitizer build's run short.
    const std::vector<float> all_thresholds = thresholds();
    std::vector<float> some_thresholds;
    for (size_t i = 0; i < all_thresholds.size(); i += 16) some_thresholds.push_back(all_thresholds[i]);
    some_thresholds.push_back(1.0f);
    for (const Levels& b : settings)
        for (int levels = 1; levels <= 3; ++levels) {
            CAPTURE(b.v2s);
            CAPTURE(levels);
            const shader::vec4 ramps = shader::lod_volume_ramps(levels, b.v2s, b.v2f, b.v3s, b.v3f);
            int nonempty[4] = {0, 0, 0, 0};
            int outside_nonempty = 0;
            for (float d = 0.0f; d <= 350.0f; d += 0.73f) {
                const shader::vec2 cuts = shader::lod_cuts(d, b.gf, b.gn, b.is, b.ifull);
                shader::vec2 bands[5] = {shader::lod_band(shader::GRASS_LOD_GEOMETRY, cuts), {}, {}, {},
                                         shader::lod_band(shader::GRASS_LOD_IMAGE, cuts)};
                for (int level = 1; level <= 3; ++level) {
                    bands[level] = shader::lod_volume_level_band(level, cuts, d, ramps);
                    const bool empty = !(bands[level].y > bands[level].x);
                    nonempty[level] += empty ? 0 : 1;
                    // A level beyond those used, or outside its distances, draws nothing.
                    const shader::vec2 range = shader::lod_volume_level_distances(level, ramps, b.gf, b.ifull);
                    if (!empty && (level > levels || d < range.x || d > range.y)) ++outside_nonempty;
                }
                // One level: level 1 is the volume's band.
                if (levels == 1) REQUIRE(bands[1] == shader::lod_band(shader::GRASS_LOD_VOLUME, cuts));
                for (float ld : kDensities)
                    for (float th : some_thresholds) {
                        int drawn = 0;
                        for (const shader::vec2& band : bands) drawn += shader::grass_blade_in_band(th, ld, band) ? 1 : 0;
                        if (drawn != (th <= ld ? 1 : 0)) {
                            CAPTURE(d);
                            CAPTURE(ld);
                            CAPTURE(th);
                            REQUIRE(drawn == (th <= ld ? 1 : 0));
                        }
                    }
            }
            CHECK(outside_nonempty == 0);
            // With Lemme's distances every level used draws somewhere.
            if (b.v3f == 160.0f)
                for (int level = 1; level <= levels; ++level) CHECK(nonempty[level] > 0);
        }
    // Lemme's table: at 65 m levels 1 and 2 share the blades, at 130 m levels 2 and 3, at 250 m level 3
    // and the image; level 1 has none left from 80 m, level 2 from 160 m.
    const shader::vec4 lemme = shader::lod_volume_ramps(3, 50, 80, 100, 160);
    const auto band = [&](int level, float d) {
        return shader::lod_volume_level_band(level, shader::lod_cuts(d, 5, 20, 200, 300), d, lemme);
    };
    CHECK(band(1, 65).y > band(1, 65).x);
    CHECK(band(2, 65).y > band(2, 65).x);
    CHECK(band(3, 65).y == band(3, 65).x);
    CHECK(band(1, 130).y == band(1, 130).x);
    CHECK(band(2, 130).y > band(2, 130).x);
    CHECK(band(3, 130).y > band(3, 130).x);
    CHECK(band(2, 250).y == band(2, 250).x);
    CHECK(band(3, 250).y > band(3, 250).x);
    CHECK(band(3, 250).y < 1.0f);  // the image has the rest
}

// ---- The transition windows grass.lod draws (lod_beyond, lod_band_interval, lod_screen_door) ----

namespace {

const std::vector<int> kWindows{shader::GRASS_LOD_WINDOW_BINARY, shader::GRASS_LOD_WINDOW_LINEAR,
                                shader::GRASS_LOD_WINDOW_SMOOTHSTEP};

}  // namespace

TEST_CASE("transition windows: the linear one is Algorithm 1 / eq 4.6, the smoothstep one eq 5.26 centred, binary is "
          "eq 5.25's complementary cut") {
    for (float ld : {0.01f, 0.3f, 0.77f, 1.0f})
        for (int k = 0; k <= 64; ++k) {
            const float c = float(k) / 64.0f;
            CAPTURE(ld);
            CAPTURE(c);
            const float eps = 0.05f;
            const float centre = c * (1.0f + 2.0f * eps) - eps;  // canopy's centred window
            for (float dth : thresholds()) {
                if (dth > ld) continue;
                const float x = dth / ld;
                // The nearer representation's share: Algorithm 1's opacity (Boulanger's slices take
                // the thresholds canopy's nearer band takes; the window's shape is his).
                const float linear = 1.0f - shader::lod_beyond(x, c, shader::GRASS_LOD_WINDOW_LINEAR, shader::LOD_OMEGA_MAX);
                const float smooth = 1.0f - shader::lod_beyond(x, c, shader::GRASS_LOD_WINDOW_SMOOTHSTEP, eps);
                if (std::abs(linear - shader::lod_far_opacity(dth, ld, c)) > 2e-4f ||
                    std::abs(smooth - shader::lod_first_opacity_smooth(dth, ld, centre, eps)) > 2e-4f ||
                    (shader::lod_band_interval(dth, ld, shader::vec2(0.0f, c), shader::GRASS_LOD_WINDOW_BINARY, eps).y > 0.0f) !=
                        shader::lod_in_first(dth, ld, c)) {
                    CAPTURE(dth);
                    CAPTURE(linear);
                    CAPTURE(smooth);
                    REQUIRE(false);
                }
            }
        }
}

TEST_CASE("transition windows: over every distance, threshold and density the bands' screen-door intervals tile 0 to 1 "
          "near to far for a kept blade, and are empty for a thinned one") {
    struct Levels {
        float gf, gn, v2s, v2f, v3s, v3f, is, ifull;
        int levels;
    };
    const std::vector<Levels> settings{{5, 20, 50, 80, 100, 160, 200, 300, 3}, {5, 20, 0, 0, 0, 0, 50, 80, 1},
                                       {10, 10, 30, 30, 50, 50, 70, 70, 3}, {0, 0, 0, 0, 0, 0, 0, 0, 1}};
    const std::vector<float> all = thresholds();
    std::vector<float> some;
    for (size_t i = 0; i < all.size(); i += 8) some.push_back(all[i]);
    some.push_back(1.0f);
    for (int window : kWindows)
        for (float width : {0.05f, 0.25f})
            for (const Levels& b : settings) {
                CAPTURE(window);
                CAPTURE(width);
                CAPTURE(b.levels);
                const shader::vec4 ramps = shader::lod_volume_ramps(b.levels, b.v2s, b.v2f, b.v3s, b.v3f);
                for (float d = 0.0f; d <= 320.0f; d += 1.37f) {
                    const shader::vec2 cuts = shader::lod_cuts(d, b.gf, b.gn, b.is, b.ifull);
                    const shader::vec2 bands[5] = {shader::lod_band(shader::GRASS_LOD_GEOMETRY, cuts),
                                                   shader::lod_volume_level_band(1, cuts, d, ramps),
                                                   shader::lod_volume_level_band(2, cuts, d, ramps),
                                                   shader::lod_volume_level_band(3, cuts, d, ramps),
                                                   shader::lod_band(shader::GRASS_LOD_IMAGE, cuts)};
                    for (float ld : kDensities) {
                        int kept = 0, split = 0;
                        for (float dth : some) {
                            float end = 0.0f;
                            bool ok = true;
                            int shared = 0;
                            for (const shader::vec2& band : bands) {
                                const shader::vec2 i = shader::lod_band_interval(dth, ld, band, window, width);
                                ok = ok && std::isfinite(i.x) && std::isfinite(i.y) && i.y >= i.x;
                                if (dth <= ld && ld > 0.0f) {
                                    ok = ok && i.x == end;  // no gap, no overlap
                                    end = i.y;
                                    shared += i.y > i.x;
                                } else {
                                    ok = ok && !(i.y > i.x);  // thinned: nowhere
                                }
                            }
                            if (dth <= ld && ld > 0.0f) {
                                ok = ok && end == 1.0f;
                                ++kept;
                                split += shared > 1;
                            }
                            if (!ok) {
                                CAPTURE(d);
                                CAPTURE(ld);
                                CAPTURE(dth);
                                REQUIRE(ok);
                            }
                        }
                        // Only the windows' blades are shared: at most 2 * width of the density at each cut
                        // inside ]0, 1[ (the levels' cuts m1, m2 are the bands' ends), none with binary cuts.
                        int inner = 0;
                        for (int k = 0; k < 4; ++k) {
                            const float cut = bands[k].y;
                            bool repeated = false;
                            for (int j = 0; j < k; ++j) repeated = repeated || bands[j].y == cut;
                            inner += cut > 0.0f && cut < 1.0f && !repeated;
                        }
                        const double windows = window == shader::GRASS_LOD_WINDOW_BINARY ? 0.0 : 2.0 * width * inner;
                        CHECK(double(split) <= windows * kept + 2.0);
                    }
                    // At the ends the one representation draws every blade whole.
                    if (d < b.gf) CHECK(shader::lod_band_interval(0.5f, 1.0f, bands[0], window, width) == shader::vec2(0.0f, 1.0f));
                    if (d >= b.ifull) CHECK(shader::lod_band_interval(0.5f, 1.0f, bands[4], window, width) == shader::vec2(0.0f, 1.0f));
                }
            }
}

TEST_CASE("transition windows: a texel's interval is its blade's at level 0, the mean of its blades' shares over a "
          "range, and the bands' intervals tile what the density keeps") {
    using shader::vec2;
    for (int window : kWindows)
        for (float width : {0.05f, 0.25f})
            for (float ld : {0.0f, 0.3f, 0.77f, 1.0f})
                for (float lo_cut : {0.0f, 0.2f, 0.5f})
                    for (float hi_cut : {0.5f, 0.8f, 1.0f}) {
                        CAPTURE(window);
                        CAPTURE(width);
                        CAPTURE(ld);
                        const vec2 band(lo_cut, hi_cut);
                        // Level 0: one threshold.
                        for (float t : {0.05f, 0.25f, 0.5f, 0.75f, 0.99f, 1.0f, 2.0f})
                            REQUIRE(shader::blade_texel_interval(vec2(t, t), ld, band, window, width) ==
                                    shader::lod_band_interval(t, ld, band, window, width));
                        // Wide ranges, narrow ones (a lookup between a level-0 texel and the next: the
                        // integral read apart from its ramp, under 1e-4 the middle), and ranges at the ends.
                        for (const vec2 range : {vec2(0.1f, 0.9f), vec2(0.2f, 0.4f), vec2(0.45f, 0.55f), vec2(0.6f, 1.0f),
                                                 vec2(0.01f, 1.0f), vec2(0.5f, 0.50001f), vec2(0.2f, 0.2003f),
                                                 vec2(0.999f, 1.0f), vec2(1e-6f, 2e-6f)}) {
                            CAPTURE(range);
                            const vec2 interval = shader::blade_texel_interval(range, ld, band, window, width);
                            // The mean share of thresholds spread evenly over the range.
                            double mean = 0.0;
                            const int n = 20000;
                            for (int i = 0; i < n; ++i) {
                                const float t = range.x + (range.y - range.x) * (float(i) + 0.5f) / float(n);
                                const vec2 b = shader::lod_band_interval(t, ld, band, window, width);
                                mean += double(b.y - b.x);
                            }
                            mean /= n;
                            // Under 1e-4 wide the range is read at its middle: within the window's steepest slope
                            // (1 / (2 width omega_0)) times half the width of the mean.
                            const double tolerance = range.y - range.x > 1e-4f ? 2e-3 : 5e-3;
                            CHECK(double(interval.y - interval.x) == doctest::Approx(mean).epsilon(0.0).scale(1.0).epsilon(tolerance));
                            CHECK(interval.y >= interval.x);
                            if (window == shader::GRASS_LOD_WINDOW_BINARY)
                                CHECK(interval.y - interval.x ==
                                      doctest::Approx(shader::blade_texel_share(range, ld, band)).epsilon(1e-5));
                            // Near, middle, far at these cuts: [0, kept) without gap or overlap.
                            const float kept = shader::blade_texel_share(range, ld, vec2(0.0f, 1.0f));
                            const vec2 near = shader::blade_texel_interval(range, ld, vec2(0.0f, lo_cut), window, width);
                            const vec2 middle = shader::blade_texel_interval(range, ld, vec2(lo_cut, hi_cut), window, width);
                            const vec2 far = shader::blade_texel_interval(range, ld, vec2(hi_cut, 1.0f), window, width);
                            CHECK(near.x == doctest::Approx(0.0f).epsilon(0.0).scale(1.0).epsilon(1e-6));
                            CHECK(near.y == doctest::Approx(middle.x).epsilon(1e-5));
                            CHECK(middle.y == doctest::Approx(far.x).epsilon(1e-5));
                            CHECK(far.y == doctest::Approx(kept).epsilon(1e-5));
                        }
                    }
}

TEST_CASE("transition windows: the screen door lies in 0 to 1 and any 8 x 8 pixels hold each of its 64 levels once") {
    // Every 8 x 8 window, aligned or not: the share of its pixels below h is h to 1/64, so a band
    // drawing an interval of length s draws s of any 8 x 8 pixels to 1/64 (a blade's shares sum to
    // one pixel in any case: the intervals tile).
    for (int oy = 0; oy < 8; ++oy)
        for (int ox = 0; ox < 8; ++ox) {
            int count[64] = {};
            for (int y = oy; y < oy + 8; ++y)
                for (int x = ox; x < ox + 8; ++x) {
                    // Pixel centres, as gl_FragCoord gives them, and the integer corner read alike.
                    const float h = shader::lod_screen_door(shader::vec2(float(x) + 0.5f, float(y) + 0.5f));
                    REQUIRE(h == shader::lod_screen_door(shader::vec2(float(x + 8 * 37), float(y + 8 * 91))));
                    REQUIRE(h > 0.0f);
                    REQUIRE(h < 1.0f);
                    const int level = int(h * 64.0f);
                    REQUIRE(std::abs(h - (float(level) + 0.5f) / 64.0f) < 1e-6f);
                    ++count[level];
                }
            for (int level = 0; level < 64; ++level) REQUIRE(count[level] == 1);
        }
    // Neighbours differ by at least 1/16 (an ordered dither, not a gradient).
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            CHECK(std::abs(shader::lod_screen_door(shader::vec2(float(x), float(y))) -
                           shader::lod_screen_door(shader::vec2(float(x + 1), float(y)))) >= 1.0f / 16.0f - 1e-6f);
}
