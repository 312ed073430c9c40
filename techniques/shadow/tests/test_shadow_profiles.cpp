// Where each shadow technique puts a straight shadow edge and how wide it makes the penumbra,
// rendered on the test device (edge_profile.hpp) and compared with the profile its footprint
// implies (footprint_models.hpp): the 50 % crossing, the 10-90 % rise and the whole profile.
// Fixed-kernel techniques are pinned to the rasterised edge and their kernel; PCSS and SSSS to
// the penumbra of eq 6.1 / 6.2, which grows with the light (Gumbau 2011, Fig 6.9). README.md
// here lists what each test pins, the tolerances, and the breakages each one catches.
#include "edge_profile.hpp"
#include "footprint_models.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace canopy;
using namespace canopy::test;

namespace {

// Tolerances, in shadow-map texels unless said otherwise. On lavapipe every profile matches its
// model to float precision (SSSS's too: its model rounds the taps to the same whole pixels). The
// allowances cover SSSS taps rounded the other way on another device (a step moves by up to half
// a pixel), other devices' rasterisation and filtering precision (1/256 texel), and crossings
// interpolated between pixel samples; a shift of half a texel, or a footprint 12 % too wide at 4
// texels (less at wider ones), exceeds them.
constexpr double kCentreTexels = 0.2;     // plus 1.5 pixels
constexpr double kWidthTexels = 0.2;      // plus 1.5 pixels and kWidthRelative of the expected width
constexpr double kWidthRelative = 0.04;
constexpr double kVisibility = 0.05;      // any sample against the model within +-1 pixel

std::string fmt_measure(const EdgeMeasure& m) {
    char text[128];
    std::snprintf(text, sizeof text, "centre %.3f, 10-90 width %.3f texels", m.centre, m.width);
    return text;
}

// The largest visibility difference of `got` from `want`, each sample compared with the model's
// range over its neighbours (+-1 pixel), so a step that lands one pixel over is not an error.
double profile_deviation(const Profile& got, const Profile& want) {
    double worst = 0.0;
    for (size_t i = 0; i < got.size(); ++i) {
        double lo = want[i].visibility, hi = lo;
        for (size_t j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, want.size() - 1); ++j) {
            lo = std::min(lo, want[j].visibility);
            hi = std::max(hi, want[j].visibility);
        }
        worst = std::max({worst, lo - got[i].visibility, got[i].visibility - hi});
    }
    return worst;
}

struct Measured {
    EdgeMeasure got;   // the rendered profile
    EdgeMeasure want;  // the model's
};

// Checks a rendered profile against its model: 50 % crossing, 10-90 % width, and the whole
// profile. Returns both measures for further checks.
Measured check_against_model(const std::string& what, const Profile& got, const Profile& want,
                             bool check_shape = true) {
    const EdgeMeasure g = measure(got), w = measure(want);
    const double pixel = pixel_texels(got);
    INFO(what, ": rendered ", fmt_measure(g), "; expected ", fmt_measure(w), " (one pixel = ", pixel, " texel)");
    // The strip must show the whole transition, or the crossings mean nothing.
    REQUIRE(w.umbra < 0.1);
    REQUIRE(w.lit > 0.9);
    CHECK(std::abs(g.centre - w.centre) <= kCentreTexels + 1.5 * pixel);
    CHECK(std::abs(g.width - w.width) <= kWidthTexels + 1.5 * pixel + kWidthRelative * w.width);
    if (check_shape) CHECK(profile_deviation(got, want) <= kVisibility);
    return {g, w};
}

using Params = std::map<std::string, ParamValue>;

Measured check_technique(const EdgeScene& e, const std::string& technique, const Params& params,
                         const std::function<double(const EdgeScene&, const ProfileSample&)>& model,
                         bool check_shape = true) {
    std::string what = technique + (e.setup.across_z ? " (edge along x)" : " (edge along z)");
    for (const auto& [name, value] : params) what += " " + name + "=" + to_string(value);
    const Profile got = render_profile(e, technique, params);
    const Profile want = model_profile(got, [&](const ProfileSample& s) { return model(e, s); });
    return check_against_model(what, got, want, check_shape);
}

EdgeSetup directional(bool across_z, float window_texels) {
    EdgeSetup s;
    s.light = LightType::directional;
    s.across_z = across_z;
    s.window_texels = window_texels;
    return s;
}

// An area light 2 above the floor, straight above the edge (0.3 texel off it), the slab's top at
// `occluder_height`, the strip wide enough for three penumbra widths.
// `camera_height` 0: the default, 0.8 of the slab's height.
EdgeScene area_light_edge(LightType type, float size, float occluder_height, int resolution, bool across_z = false,
                          float camera_height = 0.0f) {
    EdgeSetup s;
    s.light = type;
    s.light_size = size;
    s.occluder_height = occluder_height;
    s.resolution = resolution;
    s.across_z = across_z;
    s.camera_height = camera_height;
    const EdgeScene probe = make_edge_scene(s);
    s.window_texels = float(3.0 * eq61_width(probe, size) / probe.texel_floor + 8.0);
    return make_edge_scene(s);
}

}  // namespace

TEST_CASE("shadow.hard: the shadow edge is the occluder's edge, sharp to a pixel") {
    for (bool across_z : {false, true}) {
        const EdgeScene e = make_edge_scene(directional(across_z, 16.0f));
        const EdgeMeasure m = check_technique(e, "shadow.hard", {}, hard_model).got;
        // Closed form: the rasterised edge is the texel boundary nearest the geometric edge.
        CHECK(std::abs(e.boundary) <= 0.5);
        CHECK(std::abs(m.centre - e.boundary) <= kCentreTexels);
        CHECK(m.width <= kWidthTexels);
    }
    EdgeSetup spot = directional(false, 16.0f);
    spot.light = LightType::spot;
    spot.resolution = 1024;
    check_technique(make_edge_scene(spot), "shadow.hard", {}, hard_model);
}

TEST_CASE("shadow.pcf: a k x k grid spreads the edge over k - 1 texels around it") {
    for (bool across_z : {false, true}) {
        const EdgeScene e = make_edge_scene(directional(across_z, 16.0f));
        double widths[2];
        int n = 0;
        for (int k : {3, 5}) {
            const EdgeMeasure m = check_technique(e, "shadow.pcf", {{"kernel", (long long)k}},
                                                  [k](const EdgeScene& e, const ProfileSample& s) { return pcf_grid_model(e, s, k, false); }).got;
            // Closed form: k taps a texel apart make a staircase of k steps from t = boundary -
            // (k-1)/2 to boundary + (k-1)/2 around the rasterised edge.
            CHECK(std::abs(m.centre - e.boundary) <= kCentreTexels + 0.5);
            CHECK(m.width == doctest::Approx(k - 1).epsilon(0.1));
            widths[n++] = m.width;
        }
        CHECK(widths[1] / widths[0] == doctest::Approx(2.0).epsilon(0.1));  // kernel 3 -> 5 doubles the width
    }
}

TEST_CASE("shadow.pcf: Poisson-disk taps, hardware 2x2 taps and a spot light follow their footprints") {
    for (bool across_z : {false, true}) {
        const EdgeScene e = make_edge_scene(directional(across_z, 16.0f));
        check_technique(e, "shadow.pcf", {{"kernel", 5LL}, {"pattern", std::string("poisson")}},
                        [](const EdgeScene& e, const ProfileSample& s) { return pcf_poisson_model(e, s, 5); });
        check_technique(e, "shadow.pcf", {{"kernel", 3LL}, {"hardware_2x2", true}},
                        [](const EdgeScene& e, const ProfileSample& s) { return pcf_grid_model(e, s, 3, true); });
    }
    EdgeSetup spot = directional(false, 16.0f);
    spot.light = LightType::spot;
    spot.resolution = 1024;
    check_technique(make_edge_scene(spot), "shadow.pcf", {{"kernel", 5LL}},
                    [](const EdgeScene& e, const ProfileSample& s) { return pcf_grid_model(e, s, 5, false); });
}

TEST_CASE("shadow.pcss: the penumbra is eq 6.1's for the slab's depth and grows with the light (G-F6.9)") {
    // K = 11 taps (G-F6.9's setting): a staircase whose 10-90 % rise is 0.8 of the filter's
    // span, as for the physical penumbra of a square light over a straight edge: visibility
    // rises linearly over w = L (d_receiver - d_blocker) / d_blocker, 10-90 % over 0.8 w.
    const int kernel = 11;
    double previous_width = 0.0, previous_size = 0.0;
    for (float size : {0.1f, 0.2f, 0.4f}) {
        const EdgeScene e = area_light_edge(LightType::rect, size, 0.5f, 1024);
        CAPTURE(size);
        const EdgeMeasure m = check_technique(e, "shadow.pcss", {{"kernel", (long long)kernel}},
                                              [&](const EdgeScene& e, const ProfileSample& s) { return pcss_model(e, s, size, 5, kernel); }).got;
        const double physical = 0.8 * eq61_width(e, size) / e.texel_floor;  // 10-90 % of the linear ramp
        CHECK(m.width == doctest::Approx(physical).epsilon(0.1));
        CHECK(std::abs(m.centre - e.boundary) <= kCentreTexels + 0.5);  // centred on the edge
        if (previous_width > 0.0) CHECK(m.width / previous_width == doctest::Approx(size / previous_size).epsilon(0.1));
        previous_width = m.width;
        previous_size = size;
    }
}

TEST_CASE("shadow.pcss: the blocker search finds the slab's depth: a lower slab, a narrower penumbra; sphere lights") {
    // The same light over slabs at two known heights: eq 6.1 with the slab's own depth. A
    // blocker depth taken from anywhere else (the near plane, the receiver, normalised depth
    // used as distance) changes the ratio of the two widths.
    const float size = 0.4f;
    const int kernel = 11;
    double widths[2], predicted[2];
    int n = 0;
    for (float height : {0.5f, 0.3f}) {
        const EdgeScene e = area_light_edge(LightType::rect, size, height, 1024, true);
        CAPTURE(height);
        const EdgeMeasure m = check_technique(e, "shadow.pcss", {{"kernel", (long long)kernel}},
                                              [&](const EdgeScene& e, const ProfileSample& s) { return pcss_model(e, s, size, 5, kernel); }).got;
        predicted[n] = 0.8 * eq61_width(e, size) / e.texel_floor;
        CHECK(m.width == doctest::Approx(predicted[n]).epsilon(0.1));
        widths[n++] = m.width;
    }
    CHECK(widths[1] / widths[0] == doctest::Approx(predicted[1] / predicted[0]).epsilon(0.1));
    // A sphere light's width is its diameter.
    const float diameter = 0.3f;
    const EdgeScene e = area_light_edge(LightType::sphere, diameter, 0.5f, 1024);
    const EdgeMeasure m = check_technique(e, "shadow.pcss", {{"kernel", (long long)kernel}},
                                          [&](const EdgeScene& e, const ProfileSample& s) { return pcss_model(e, s, diameter, 5, kernel); }).got;
    CHECK(m.width == doctest::Approx(0.8 * eq61_width(e, diameter) / e.texel_floor).epsilon(0.1));
}

TEST_CASE("shadow.ssss: the screen-space Gaussian rises over eq 6.2's width, which grows with the light (G-F6.9)") {
    // SSSS takes eq 6.2's width as the Gaussian's 10-90 % rise (sigma = w / 2.563, in pixels
    // at the observer's distance); 11 discrete taps over +-3 sigma rise over 0.94 w. The whole
    // profile pins the coarse map's dilation too: a reach short of the blur's 3 sigma leaves
    // the end of the penumbra unblurred (a step of 0.06 at light 0.4).
    for (bool across_z : {false, true}) {
        double previous_width = 0.0, previous_size = 0.0;
        for (float size : {0.1f, 0.2f, 0.4f}) {
            const EdgeScene e = area_light_edge(LightType::rect, size, 0.5f, 512, across_z);
            CAPTURE(size);
            const Profile got = render_profile(e, "shadow.ssss", {});
            const double pixel = pixel_texels(got);
            const Profile want = ssss_model(e, got, size, 11);
            const EdgeMeasure m = check_against_model(std::string("shadow.ssss") + (across_z ? " (edge along x)" : " (edge along z)"), got, want).got;
            const double width = eq61_width(e, size) / e.texel_floor;  // eq 6.2 at the receiver, in texels
            CHECK(m.width == doctest::Approx(width).epsilon(0.15));
            CHECK(std::abs(m.centre - e.boundary) <= kCentreTexels + 1.5 * pixel);
            if (previous_width > 0.0) CHECK(m.width / previous_width == doctest::Approx(size / previous_size).epsilon(0.1));
            previous_width = m.width;
            previous_size = size;
        }
    }
    // A sphere light's width is its diameter; a lower slab narrows the penumbra.
    for (float height : {0.5f, 0.3f}) {
        const float diameter = 0.3f;
        const EdgeScene e = area_light_edge(LightType::sphere, diameter, height, 512);
        CAPTURE(height);
        const Profile got = render_profile(e, "shadow.ssss", {});
        const Profile want = ssss_model(e, got, diameter, 11);
        const EdgeMeasure m = check_against_model("shadow.ssss sphere light", got, want).got;
        CHECK(m.width == doctest::Approx(eq61_width(e, diameter) / e.texel_floor).epsilon(0.15));
    }
}

TEST_CASE("shadow.ssss: a wide penumbra seen from close by keeps its width (taps on the tangent plane are kept)") {
    // The camera 0.25 above the floor under a 1.2 rect light: the penumbra is 1.6 times as wide
    // as the camera is high, so taps a third of the camera's height to the side are already 5 %
    // farther from it than the centre. They lie on the centre's tangent plane (the floor), so the
    // depth test keeps them; a test against the centre's own distance drops them (without lazy
    // shadowing: 10-90 % width 13.7 texels, 50 % 8 texels into the shadow) or, in the second
    // pass, puts hard shadows in their place (edge along z: 17.7 texels instead of the model's
    // 30.5). Eq 6.2 divides by the floor's depth along the view axis, the same for every pixel
    // here, so the penumbra keeps eq 6.1's width on the floor (dividing by the Euclidean
    // distance instead drew it 22 % narrower: 30.5 texels against 39).
    const float size = 1.2f;
    for (bool across_z : {false, true}) {
        const EdgeScene e = area_light_edge(LightType::rect, size, 0.5f, 1024, across_z, 0.25f);
        const std::string what = std::string("shadow.ssss from 0.25 above the floor") + (across_z ? " (edge along x)" : " (edge along z)");
        for (bool lazy : {true, false}) {
            CAPTURE(lazy);
            const Profile got = render_profile(e, "shadow.ssss", {{"lazy", lazy}});
            const double pixel = pixel_texels(got);
            const Profile want = ssss_model(e, got, size, 11);
            const EdgeMeasure m = check_against_model(what + (lazy ? "" : " lazy=false"), got, want).got;
            CHECK(std::abs(m.centre - e.boundary) <= kCentreTexels + 1.5 * pixel);
            CHECK(m.width == doctest::Approx(eq61_width(e, size) / e.texel_floor).epsilon(0.15));  // eq 6.1 on the floor
        }
    }
}

namespace {

// A prefiltered technique at filter widths 5 and 9, both map axes: the model's profile, and the
// width growing with the filter as the footprint says (9/5 for the linear ramp of VSM, ESM,
// EVSM and MSM, whose bounds are exact for one blocker depth over one receiver depth).
void check_prefiltered(const std::string& technique, const Params& params, const MomentModel& model,
                       bool check_shape = true) {
    for (bool across_z : {false, true}) {
        const EdgeScene e = make_edge_scene(directional(across_z, 24.0f));
        Measured m[2];
        int n = 0;
        for (int filter : {5, 9}) {
            Params p = params;
            p["filter"] = (long long)filter;
            m[n++] = check_technique(e, technique, p,
                                     [&](const EdgeScene& e, const ProfileSample& s) { return moment_model(e, s, model, filter); },
                                     check_shape);
        }
        CAPTURE(technique);
        if (m[0].want.width > 1.0)
            CHECK(m[1].got.width / m[0].got.width == doctest::Approx(m[1].want.width / m[0].want.width).epsilon(0.1));
    }
}

}  // namespace

TEST_CASE("shadow.vsm: a box prefilter of `filter` texels makes a linear ramp of that width on the edge") {
    const EdgeScene e = make_edge_scene(directional(false, 24.0f));
    const EdgeMeasure m = check_technique(e, "shadow.vsm", {{"filter", 5LL}},
                                          [](const EdgeScene& e, const ProfileSample& s) { return moment_model(e, s, moments::vsm(), 5); }).got;
    // Closed form: Chebyshev is exact for two depths with the receiver at the far one, so the
    // visibility is 1 - (blocked fraction of the 5-texel box): a ramp of 5 texels, 10-90 % over 4.
    CHECK(m.width == doctest::Approx(4.0).epsilon(0.05));
    CHECK(std::abs(m.centre - e.boundary) <= kCentreTexels);
    check_prefiltered("shadow.vsm", {}, moments::vsm());
}

TEST_CASE("shadow.esm: exp(c z) prefiltered over `filter` texels, linear and log-space storage") {
    check_prefiltered("shadow.esm", {}, moments::esm());
    // log_space: position and width; the shape is checked by the next test case.
    check_prefiltered("shadow.esm", {{"log_space", true}}, moments::esm(), false);
}

// Issue 7, section 3: esm_visibility_log is looked up with a bilinear filter of c z, which is not
// log-space filtering: between texel centres the profile sags by up to 0.1 (10-90 % width 3.66
// instead of 4.0 texels at filter 5). The fix belongs to the ESM defect; until it lands, this
// shape check reports without failing.
TEST_CASE("shadow.esm: log-space storage renders the same profile as linear storage") {
    for (bool across_z : {false, true}) {
        const EdgeScene e = make_edge_scene(directional(across_z, 24.0f));
        check_technique(e, "shadow.esm", {{"log_space", true}, {"filter", 5LL}},
                        [](const EdgeScene& e, const ProfileSample& s) { return moment_model(e, s, moments::esm(), 5); });
    }
}

TEST_CASE("shadow.gauss-cdf: the Gaussian CDF of the box-filtered moments, lit at the mean (eq 7.4)") {
    // Closed form: for a blocked fraction f of the box, v = 1 - erf(sqrt(f / (2 (1 - f)))), so
    // 50 % falls where f = 0.31: 0.19 of the filter width (0.94 texel) onto the lit side.
    const EdgeScene e = make_edge_scene(directional(false, 24.0f));
    const EdgeMeasure m = check_technique(e, "shadow.gauss-cdf", {{"filter", 5LL}},
                                          [](const EdgeScene& e, const ProfileSample& s) { return moment_model(e, s, moments::gauss_cdf(), 5); }).got;
    const double x2 = 0.476936 * 0.476936;  // erf(x) = 0.5
    const double f_half = 2.0 * x2 / (1.0 + 2.0 * x2);
    CHECK(m.centre - e.boundary == doctest::Approx((0.5 - f_half) * 5.0).epsilon(0.1));
    check_prefiltered("shadow.gauss-cdf", {}, moments::gauss_cdf());
}

TEST_CASE("shadow.power-cdf: min, max and mean over `filter` texels put a sharp edge r texels onto the lit side") {
    // eq 7.7 for a receiver at the window's maximum depth is 0 whenever the window holds a
    // blocker: the shadow grows by the filter radius r (README: outer penumbrae), and stays sharp.
    for (int filter : {5, 9}) {
        const EdgeScene e = make_edge_scene(directional(false, 24.0f));
        const EdgeMeasure m = check_technique(e, "shadow.power-cdf", {{"filter", (long long)filter}},
                                              [filter](const EdgeScene& e, const ProfileSample& s) { return moment_model(e, s, moments::power_cdf(), filter); }).got;
        const int r = filter / 2;
        CHECK(m.centre - e.boundary >= r - kCentreTexels);
        CHECK(m.centre - e.boundary <= r + 1.0 + kCentreTexels);
        CHECK(m.width <= 1.0);
    }
    check_prefiltered("shadow.power-cdf", {}, moments::power_cdf());
}

TEST_CASE("shadow.evsm: exponentially warped moments prefiltered over `filter` texels, 4 and 2 components") {
    check_prefiltered("shadow.evsm", {}, moments::evsm(4));
    check_prefiltered("shadow.evsm", {{"components", std::string("2")}}, moments::evsm(2));
}

TEST_CASE("shadow.msm: four moments prefiltered over `filter` texels, Hamburger reconstruction") {
    check_prefiltered("shadow.msm", {}, moments::msm());
    check_prefiltered("shadow.msm", {{"precision", std::string("unorm16")}, {"moment_bias", 6e-5}}, moments::msm(6e-5));
}
