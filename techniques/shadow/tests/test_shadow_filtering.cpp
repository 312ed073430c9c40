// The shadow-filtering visibility functions (../shaders/shadow_filtering.h), checked as C++:
// hand-computed values, the papers' equations, and numerical stability at the extremes. Every
// visibility must be finite, in [0, 1], non-increasing in the receiver depth and 1 in front of
// its occluders; a NaN anywhere fails with a message naming the function and its inputs.
#include "core/registry.hpp"
#include "../common/shadow_technique.hpp"
#include "../shaders/shadow_common.h"
#include "../shaders/shadow_filtering.h"
#include "../evsm/evsm_params.h"

#include <doctest/doctest.h>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace canopy::shader;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Round to IEEE half precision and back (what an rgba16f map stores).
float half(float x) { return glm::unpackHalf1x16(glm::packHalf1x16(x)); }
// Round to 16-bit unorm and back (what an rgba16 unorm map stores).
float unorm16(float x) { return std::round(std::clamp(x, 0.0f, 1.0f) * 65535.0f) / 65535.0f; }

std::string describe(const char* what, float value) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "%s = %.9g", what, value);
    return buffer;
}

// A filter footprint: depths and normalised weights, with the statistics each technique stores.
// Statistics are filtered in float, as the GPU does; `quantise` rounds every stored texel and the
// filtered result (the separable blur writes back to the map) to the map's 16-bit format.
struct Footprint {
    std::vector<float> z;
    std::vector<float> w;
    std::string label;
};

Footprint mixture(float za, float zb, float wa, std::string label = "") {
    if (label.empty()) {
        char buffer[96];
        std::snprintf(buffer, sizeof buffer, "mixture %.4f x %.6g + %.4f x %.6g", wa, za, 1.0f - wa, zb);
        label = buffer;
    }
    return {{za, zb}, {wa, 1.0f - wa}, label};
}

struct Stats {
    glm::vec2 vsm{0.0f};
    float z_min = 1.0f, z_max = 0.0f, mean = 0.0f;
    float esm_linear = 0.0f;
    float esm_log = 0.0f;
    glm::vec4 evsm{0.0f};
    glm::vec4 msm{0.0f};  // decoded b1..b4
};

struct StatsOptions {
    float esm_c = 20.0f;
    float evsm_pos = 20.0f;
    float evsm_neg = 5.0f;
    std::function<float(float)> quantise = [](float x) { return x; };
};

Stats statistics(const Footprint& f, const StatsOptions& o) {
    const auto& q = o.quantise;
    Stats s;
    glm::vec4 msm_stored(0.0f);
    float log_acc = 0.0f;
    bool first = true;
    for (size_t i = 0; i < f.z.size(); ++i) {
        const float z = f.z[i], w = f.w[i];
        if (w <= 0.0f) continue;  // a tap of weight 0 is not fetched (0 x inf would be NaN)
        s.vsm += w * glm::vec2(q(z), q(z * z));
        s.z_min = std::min(s.z_min, q(z));
        s.z_max = std::max(s.z_max, q(z));
        s.mean += w * q(z);
        s.esm_linear += w * q(std::exp(o.esm_c * z));
        // Log-space filtering, accumulated with the shared helper.
        log_acc = first ? q(o.esm_c * z) + std::log(w) : log_sum_exp_weighted(log_acc, 1.0f, q(o.esm_c * z), w);
        first = false;
        const glm::vec4 m = evsm_moments(z, o.evsm_pos, o.evsm_neg);
        s.evsm += w * glm::vec4(q(m.x), q(m.y), q(m.z), q(m.w));
        const glm::vec4 e = msm_encode(z);
        msm_stored += w * glm::vec4(q(e.x), q(e.y), q(e.z), q(e.w));
    }
    s.vsm = {q(s.vsm.x), q(s.vsm.y)};
    s.z_min = q(s.z_min);
    s.z_max = q(s.z_max);
    s.mean = q(s.mean);
    s.esm_linear = q(s.esm_linear);
    s.esm_log = q(log_acc);
    s.evsm = {q(s.evsm.x), q(s.evsm.y), q(s.evsm.z), q(s.evsm.w)};
    s.msm = msm_decode({q(msm_stored.x), q(msm_stored.y), q(msm_stored.z), q(msm_stored.w)});
    return s;
}

// Sweeps z_r and records the first problem of each kind; CHECK_MESSAGE afterwards reports it.
struct Sweep {
    std::string name;
    int non_finite = 0, out_of_range = 0, rises = 0, not_lit = 0;
    float worst_rise = 0.0f;
    std::string first_non_finite, first_out_of_range, first_rise, first_not_lit;

    void run(const std::string& context, const std::function<float(float)>& visibility, float lit_up_to,
             float lit_tolerance, float rise_tolerance, int steps = 4096) {
        float previous = kInf;
        for (int i = -64; i <= steps + 64; ++i) {
            const float z_r = float(i) / float(steps);  // [-1.6 %, 101.6 %] of the depth range
            const float v = visibility(z_r);
            const auto where = [&] {
                char buffer[256];
                std::snprintf(buffer, sizeof buffer, "%s: %s, z_r = %.9g, v = %.9g", name.c_str(), context.c_str(), z_r, v);
                return std::string(buffer);
            };
            if (!std::isfinite(v)) {
                if (non_finite++ == 0) first_non_finite = where();
                continue;
            }
            if (v < 0.0f || v > 1.0f) {
                if (out_of_range++ == 0) first_out_of_range = where();
            }
            if (v > previous + rise_tolerance) {
                if (rises++ == 0) first_rise = where();
            }
            if (std::isfinite(previous)) worst_rise = std::max(worst_rise, v - previous);
            if (z_r <= lit_up_to && v < 1.0f - lit_tolerance) {
                if (not_lit++ == 0) first_not_lit = where();
            }
            previous = v;
        }
    }

    void report(bool check_monotone = true, bool check_lit = true) const {
        CHECK_MESSAGE(non_finite == 0, "NaN/inf: ", first_non_finite);
        CHECK_MESSAGE(out_of_range == 0, "outside [0, 1]: ", first_out_of_range);
        if (check_monotone) CHECK_MESSAGE(rises == 0, "increases with z_r: ", first_rise, " (worst rise ", worst_rise, ")");
        if (check_lit) CHECK_MESSAGE(not_lit == 0, "not lit in front of every occluder: ", first_not_lit);
    }
};

// Depth distributions from actual footprints: two-depth mixtures (an occluder edge), a few
// depths, a cleared texel (depth 1) beside an occluder, depths at 0 and 1, and single depths.
std::vector<Footprint> footprints() {
    std::vector<Footprint> out;
    std::mt19937 rng(20110601);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 40; ++i) out.push_back(mixture(u(rng), u(rng), u(rng)));
    for (int i = 0; i < 10; ++i) {  // close pairs: nearly a single depth
        const float z = u(rng);
        out.push_back(mixture(z, std::min(1.0f, z + 1e-3f * u(rng)), u(rng)));
    }
    for (int i = 0; i < 20; ++i) {
        Footprint f;
        const int n = 3 + i % 6;
        float total = 0.0f;
        for (int k = 0; k < n; ++k) {
            f.z.push_back(u(rng));
            f.w.push_back(0.05f + u(rng));
            total += f.w.back();
        }
        for (float& w : f.w) w /= total;
        f.label = "random set " + std::to_string(i);
        out.push_back(f);
    }
    out.push_back(mixture(0.3f, 1.0f, 0.5f));
    out.push_back(mixture(0.0f, 1.0f, 0.5f));
    out.push_back(mixture(0.0f, 0.0f, 0.5f, "single depth 0"));
    out.push_back(mixture(1.0f, 1.0f, 0.5f, "single depth 1"));
    for (float z : {0.001f, 0.25f, 0.5f, 0.75f, 0.999f}) out.push_back(mixture(z, z, 1.0f, describe("single depth", z)));
    return out;
}

float footprint_min(const Footprint& f) { return *std::min_element(f.z.begin(), f.z.end()); }

// A technique's plan for `given` parameters (the rest at their defaults): what its shaders get.
canopy::ShadowPlan plan_of(const std::string& technique, const std::map<std::string, canopy::ParamValue>& given = {}) {
    const auto& t = dynamic_cast<const canopy::ShadowTechnique&>(*canopy::TechniqueRegistry::instance().find(technique));
    return t.plan(canopy::ParamSet::resolve(t.params(), given, {}, {}, technique));
}

constexpr float kMinVariance = 1e-6f;
constexpr float kMsmBias32 = 3e-5f;
constexpr float kMsmBias16 = 6e-5f;

}  // namespace

// ---------------------------------------------------------------------------------------------
TEST_CASE("Chebyshev upper bound: hand-computed values (Gumbau eq 2.1-2.2)") {
    const glm::vec2 m(0.5f, 0.26f);  // mean 0.5, variance 0.01
    CHECK(chebyshev_upper_bound(m, 0.6f, 0.0f) == doctest::Approx(0.01 / (0.01 + 0.01)).epsilon(1e-5));
    CHECK(chebyshev_upper_bound(m, 0.7f, 0.0f) == doctest::Approx(0.01 / (0.01 + 0.04)).epsilon(1e-5));
    CHECK(chebyshev_upper_bound(m, 1.0f, 0.0f) == doctest::Approx(0.01 / (0.01 + 0.25)).epsilon(1e-5));
    CHECK(chebyshev_upper_bound(m, 0.5f, 0.0f) == 1.0f);  // at the mean: lit (eq 2.2)
    CHECK(chebyshev_upper_bound(m, 0.2f, 0.0f) == 1.0f);  // in front: lit
    // min_variance replaces a smaller variance: a single depth at 0.5 with floor 1e-4.
    CHECK(chebyshev_upper_bound({0.5f, 0.25f}, 0.51f, 1e-4f) == doctest::Approx(0.5).epsilon(1e-4));
    // ... and leaves a larger one alone.
    CHECK(chebyshev_upper_bound(m, 0.6f, 1e-4f) == doctest::Approx(0.5).epsilon(1e-5));
}

TEST_CASE("Chebyshev and Gaussian CDF at zero, negative and huge variance") {
    // (0.5, 0.25 - 1e-9): the variance is negative after cancellation.
    for (glm::vec2 m : {glm::vec2(0.5f, 0.25f), glm::vec2(0.5f, 0.25f - 1e-9f), glm::vec2(0.5f, 0.2f)}) {
        for (float min_variance : {0.0f, -1.0f, 1e-12f}) {
            CAPTURE(m.y);
            CAPTURE(min_variance);
            for (bool exact : {false, true}) {
                CHECK(chebyshev_upper_bound(m, 0.5f, min_variance) == 1.0f);
                CHECK(gaussian_cdf_visibility(m, 0.5f, min_variance, exact) == 1.0f);
                // Just behind the mean: the limit sigma -> 0 is a step to 0. Never NaN.
                const float behind = std::nextafter(0.5f, 1.0f);
                const float c = chebyshev_upper_bound(m, behind, min_variance);
                const float g = gaussian_cdf_visibility(m, behind, min_variance, exact);
                CHECK_MESSAGE(std::isfinite(c), describe("chebyshev", c));
                CHECK_MESSAGE(std::isfinite(g), describe("gaussian", g));
                CHECK(chebyshev_upper_bound(m, 0.6f, min_variance) <= 1e-6f);
                CHECK(gaussian_cdf_visibility(m, 0.6f, min_variance, exact) <= 1e-6f);
                // z_r far beyond the mean.
                CHECK(chebyshev_upper_bound(m, 1e30f, min_variance) == 0.0f);
                CHECK(gaussian_cdf_visibility(m, 1e30f, min_variance, exact) == 0.0f);
            }
        }
    }
    // Zero variance with (z_r - mean)^2 below the float range: 0 / 0 must not happen.
    for (bool exact : {false, true}) {
        CHECK(chebyshev_upper_bound({0.0f, 0.0f}, 1e-30f, 0.0f) == 0.0f);
        CHECK(gaussian_cdf_visibility({0.0f, 0.0f}, 1e-30f, 0.0f, exact) == doctest::Approx(1.0f - erf_accurate(1e-10f / std::sqrt(2.0f))));
        CHECK(chebyshev_upper_bound({1e-30f, 0.0f}, 2e-30f, 0.0f) == 0.0f);
    }
    // Infinite moments (a storage overflow) stay finite.
    for (glm::vec2 m : {glm::vec2(kInf, kInf), glm::vec2(0.5f, kInf), glm::vec2(-kInf, kInf)}) {
        for (float z_r : {0.0f, 0.5f, 1.0f, 1e30f}) {
            const float c = chebyshev_upper_bound(m, z_r, 1e-6f);
            CHECK_MESSAGE((std::isfinite(c) && c >= 0.0f && c <= 1.0f), describe("chebyshev of infinite moments", c));
            const float g = gaussian_cdf_visibility(m, z_r, 1e-6f, true);
            CHECK_MESSAGE((std::isfinite(g) && g >= 0.0f && g <= 1.0f), describe("gaussian of infinite moments", g));
        }
    }
}

TEST_CASE("light-bleeding reduction is linstep(amount, 1, p)") {
    CHECK(reduce_light_bleeding(0.3f, 0.0f) == doctest::Approx(0.3f));
    CHECK(reduce_light_bleeding(0.2f, 0.3f) == 0.0f);
    CHECK(reduce_light_bleeding(0.65f, 0.3f) == doctest::Approx(0.5f));
    for (float amount : {-0.5f, 0.0f, 0.3f, 0.95f, 0.9999f, 1.0f, 2.0f}) {
        CAPTURE(amount);
        CHECK(reduce_light_bleeding(1.0f, amount) == 1.0f);  // lit stays lit
        CHECK(reduce_light_bleeding(0.0f, amount) == 0.0f);
        float previous = -1.0f;
        for (int i = 0; i <= 1000; ++i) {
            const float v = reduce_light_bleeding(float(i) / 1000.0f, amount);
            REQUIRE_MESSAGE(std::isfinite(v), describe("reduce_light_bleeding", v));
            CHECK(v >= previous);  // non-decreasing in p, so visibility stays non-increasing in z_r
            previous = v;
        }
    }
}

// ---------------------------------------------------------------------------------------------
TEST_CASE("ESM: hand-computed values, linear and log storage") {
    const float c = 10.0f, z_o = 0.4f;
    CHECK(esm_visibility(std::exp(c * z_o), 0.5f, c) == doctest::Approx(std::exp(-1.0)).epsilon(1e-5));
    CHECK(esm_visibility_log(c * z_o, 0.5f, c) == doctest::Approx(std::exp(-1.0)).epsilon(1e-6));
    CHECK(esm_visibility_log(c * z_o, 0.3f, c) == 1.0f);  // in front: clamped to 1
    // Planar receiver: 1 in log storage, up to one ulp where the compiler or GPU fuses
    // filtered_log - c z_r into one FMA (the stored c z_o was rounded, the fused product is not).
    CHECK(esm_visibility_log(c * z_o, z_o, c) >= 1.0f - 0x1p-23f);
    CHECK(esm_visibility(std::exp(c * z_o), z_o, c) >= 1.0f - 1e-6f);  // linear: up to exp/log rounding
    // Mixture: 0.5 e^{c 0.2} + 0.5 e^{c 0.6} at z_r = 0.7.
    const double expect = 0.5 * std::exp(10.0 * (0.2 - 0.7)) + 0.5 * std::exp(10.0 * (0.6 - 0.7));
    const float lin = 0.5f * std::exp(2.0f) + 0.5f * std::exp(6.0f);
    CHECK(esm_visibility(lin, 0.7f, c) == doctest::Approx(expect).epsilon(1e-5));
    CHECK(esm_visibility_log(log_sum_exp_weighted(2.0f, 0.5f, 6.0f, 0.5f), 0.7f, c) == doctest::Approx(expect).epsilon(1e-5));
    // Log storage has no overflow: c = 1000 still gives exp(c (z_o - z_r)).
    CHECK(esm_visibility_log(1000.0f * 0.5f, 0.501f, 1000.0f) == doctest::Approx(std::exp(-1.0)).epsilon(1e-3));
}

TEST_CASE("ESM exponents near and beyond fp16 (c ~ 11) and fp32 (c ~ 88) overflow") {
    struct Case { float c; bool half_storage; };
    for (Case k : {Case{10.0f, true}, Case{11.0f, true}, Case{11.09f, true}, Case{11.2f, true}, Case{20.0f, true},
                   Case{80.0f, false}, Case{88.0f, false}, Case{88.7f, false}, Case{89.0f, false},
                   Case{100.0f, false}, Case{1000.0f, false}}) {
        StatsOptions o;
        o.esm_c = k.c;
        if (k.half_storage) o.quantise = half;
        for (const Footprint& f : {mixture(0.2f, 0.9f, 0.5f), mixture(1.0f, 1.0f, 1.0f, "single depth 1"),
                                   mixture(0.0f, 1.0f, 0.3f), mixture(0.95f, 0.99f, 0.5f)}) {
            const Stats s = statistics(f, o);
            Sweep lin{describe(k.half_storage ? "esm fp16, c" : "esm fp32, c", k.c)};
            lin.run(f.label, [&](float z_r) { return esm_visibility(s.esm_linear, z_r, k.c); }, -1.0f, 0.0f, 0.0f);
            lin.report(true, false);
            Sweep lg{describe(k.half_storage ? "esm log fp16, c" : "esm log fp32, c", k.c)};
            lg.run(f.label, [&](float z_r) { return esm_visibility_log(s.esm_log, z_r, k.c); }, -1.0f, 0.0f, 0.0f);
            lg.report(true, false);
        }
        // Below the overflow bound a planar receiver is lit (up to the storage's rounding);
        // above it the stored value is inf and is read as FLT_MAX: finite, but no longer exact.
        const float stored = k.half_storage ? half(std::exp(k.c * 1.0f)) : std::exp(k.c * 1.0f);
        const float v = esm_visibility(stored, 1.0f, k.c);
        CAPTURE(k.c);
        CHECK_MESSAGE(std::isfinite(v), describe("esm planar at z = 1", v));
        if (std::isfinite(stored)) CHECK(v >= (k.half_storage ? 1.0f - 1e-3f : 1.0f - 1e-5f));
    }
    // The bounds themselves: fp16 stores exp(c) up to c = ln 65504 = 11.09, fp32 up to 88.72.
    CHECK(std::isfinite(half(std::exp(11.0f))));
    CHECK(std::isinf(half(std::exp(11.2f))));
    CHECK(std::isfinite(std::exp(88.7f)));
    CHECK(std::isinf(std::exp(88.8f)));
}

TEST_CASE("log_sum_exp_weighted is log(wa e^a + wb e^b) without overflow") {
    CHECK(log_sum_exp_weighted(1.0f, 0.25f, 2.0f, 0.75f) ==
          doctest::Approx(std::log(0.25 * std::exp(1.0) + 0.75 * std::exp(2.0))).epsilon(1e-6));
    // e^1000 overflows float; the stable form does not.
    CHECK(log_sum_exp_weighted(1000.0f, 0.5f, 999.0f, 0.5f) ==
          doctest::Approx(1000.0 + std::log(0.5 + 0.5 * std::exp(-1.0))).epsilon(1e-6));
    CHECK(log_sum_exp_weighted(-1000.0f, 0.5f, -1001.0f, 0.5f) ==
          doctest::Approx(-1000.0 + std::log(0.5 + 0.5 * std::exp(-1.0))).epsilon(1e-6));
    // A zero weight drops its term, however large its log.
    CHECK(log_sum_exp_weighted(1000.0f, 0.0f, 2.0f, 0.5f) == doctest::Approx(2.0 + std::log(0.5)).epsilon(1e-6));
    CHECK(log_sum_exp_weighted(2.0f, 0.5f, 1000.0f, 0.0f) == doctest::Approx(2.0 + std::log(0.5)).epsilon(1e-6));
    const float both_zero = log_sum_exp_weighted(1.0f, 0.0f, 2.0f, 0.0f);
    CHECK_MESSAGE(std::isfinite(both_zero), describe("both weights zero", both_zero));
}

// The log-space ESM lookup: texels hold ln E[exp(c z)]; a bilinear lookup must blend the
// exponentials. Blending the logs (what a LINEAR sampler does) is a geometric mean.
TEST_CASE("ESM log-space lookup blends exponentials, not logs") {
    CHECK(bilinear_weights({0.25f, 0.5f}) == glm::vec4(0.375f, 0.125f, 0.375f, 0.125f));
    const float c = 80.0f;  // the technique's default exponent
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec4 z(u(rng), u(rng), u(rng), u(rng));
        const glm::vec2 f(u(rng), u(rng));
        const glm::vec4 w = bilinear_weights(f);
        double linear = 0.0;  // E[exp(c z)] in double
        for (int k = 0; k < 4; ++k) linear += double(w[k]) * std::exp(double(c) * z[k]);
        const float blended = esm_log_bilinear(c * z, f);
        worst = std::max(worst, std::abs(double(blended) - std::log(linear)));
        // Visibility at a receiver behind all four depths: the linear filter's value.
        const float z_r = 1.0f;
        const double expect = std::min(1.0, linear * std::exp(-double(c) * z_r));
        CHECK(esm_visibility_log(blended, z_r, c) == doctest::Approx(expect).epsilon(2e-4));
    }
    CHECK(worst < 2e-5);
    // The audit's failure: an edge between z = 0.2 and 0.9 looked up halfway, receiver at 0.9. The
    // exponentials give ~0.5 (half the footprint is the receiver's own depth); the logs' blend
    // gives exp(c (0.55 - 0.9)) ~ 7e-13.
    const glm::vec4 edge = c * glm::vec4(0.2f, 0.9f, 0.2f, 0.9f);
    const float v = esm_visibility_log(esm_log_bilinear(edge, {0.5f, 0.5f}), 0.9f, c);
    CHECK(v == doctest::Approx(0.5).epsilon(1e-4));
    const float logs_blended = glm::dot(bilinear_weights({0.5f, 0.5f}), edge);
    CHECK(esm_visibility_log(logs_blended, 0.9f, c) < 1e-10f);
    // Weight 0 drops a texel however large its log; extremes stay finite.
    CHECK(esm_log_bilinear({1.0f, 1e30f, 1.0f, 1e30f}, {0.0f, 0.3f}) == doctest::Approx(1.0f));
    for (glm::vec4 logs : {glm::vec4(-1e30f), glm::vec4(1e30f), glm::vec4(0.0f, 1e4f, -1e4f, 0.0f)}) {
        for (glm::vec2 f : {glm::vec2(0.0f), glm::vec2(1.0f), glm::vec2(0.5f), glm::vec2(-1.0f, 2.0f)}) {
            const float l = esm_log_bilinear(logs, f);
            CHECK_MESSAGE(std::isfinite(l), describe("esm_log_bilinear", l));
            const float vis = esm_visibility_log(l, 0.5f, c);
            CHECK_MESSAGE((std::isfinite(vis) && vis >= 0.0f && vis <= 1.0f), describe("esm log visibility", vis));
        }
    }
}

// ---------------------------------------------------------------------------------------------
TEST_CASE("erf approximations: measured error against std::erf") {
    double worst_winitzki = 0.0, worst_winitzki_at = 0.0, worst_winitzki_rel = 0.0;
    double worst_accurate = 0.0, worst_accurate_at = 0.0;
    int winitzki_falls = 0, accurate_falls = 0, non_finite = 0;
    std::string first_non_finite;
    float previous_w = -2.0f, previous_a = -2.0f;
    for (int i = -600000; i <= 600000; ++i) {
        const float x = float(i) * 1e-5f;  // [-6, 6]
        const double exact = std::erf(double(x));
        const float w = erf_winitzki(x), a = erf_accurate(x);
        if (!std::isfinite(w) || !std::isfinite(a)) {
            if (non_finite++ == 0) first_non_finite = describe("erf not finite at x", x);
            continue;
        }
        if (std::abs(w - exact) > worst_winitzki) {
            worst_winitzki = std::abs(w - exact);
            worst_winitzki_at = x;
        }
        if (x != 0.0f) worst_winitzki_rel = std::max(worst_winitzki_rel, std::abs(w - exact) / std::abs(exact));
        if (std::abs(a - exact) > worst_accurate) {
            worst_accurate = std::abs(a - exact);
            worst_accurate_at = x;
        }
        winitzki_falls += w < previous_w;
        accurate_falls += a < previous_a;
        previous_w = w;
        previous_a = a;
    }
    CHECK_MESSAGE(non_finite == 0, first_non_finite);
    MESSAGE("erf_winitzki max |error| ", worst_winitzki, " at x = ", worst_winitzki_at, ", max relative ", worst_winitzki_rel);
    MESSAGE("erf_accurate max |error| ", worst_accurate, " at x = ", worst_accurate_at);
    CHECK(worst_winitzki < 3.4e-4);       // documented in shadow_filtering.h: 3.3e-4 absolute
    CHECK(worst_winitzki_rel < 3.6e-4);   // and 3.5e-4 relative
    CHECK(worst_accurate < 1.6e-7);       // documented in shadow_filtering.h: 1.6e-7
    CHECK_MESSAGE(winitzki_falls == 0, "erf_winitzki decreases somewhere");
    CHECK_MESSAGE(accurate_falls == 0, "erf_accurate decreases somewhere");
    // Odd, 0 at 0, +-1 at +-inf, no overflow for huge arguments.
    for (float x : {1e-30f, 1e-8f, 0.3f, 2.0f, 1e10f, kInf}) {
        CHECK(erf_winitzki(-x) == -erf_winitzki(x));
        CHECK(erf_accurate(-x) == -erf_accurate(x));
    }
    // The series and erfc pieces of erf_accurate meet at 0.75 without a step down.
    CHECK(erf_accurate(std::nextafter(0.75f, 0.0f)) <= erf_accurate(0.75f));
    CHECK(erf_accurate(0.75f) == doctest::Approx(std::erf(0.75)).epsilon(2e-7));
    CHECK(erf_winitzki(0.0f) == 0.0f);
    CHECK(erf_accurate(0.0f) == 0.0f);
    CHECK(erf_winitzki(kInf) == 1.0f);
    CHECK(erf_accurate(kInf) == 1.0f);
    // Winitzki's formula with the paper's a = 8(pi - 3) / (3 pi (4 - pi)), evaluated in double.
    const double a = 8.0 * (std::numbers::pi - 3.0) / (3.0 * std::numbers::pi * (4.0 - std::numbers::pi));
    CHECK(a == doctest::Approx(0.140012).epsilon(1e-6));
    for (double x : {0.1, 0.5, 1.0, 1.35, 2.0, 3.0}) {
        const double formula = std::sqrt(1.0 - std::exp(-x * x * (4.0 / std::numbers::pi + a * x * x) / (1.0 + a * x * x)));
        CAPTURE(x);
        CHECK(erf_winitzki(float(x)) == doctest::Approx(formula).epsilon(1e-6));
    }
    // Small arguments keep their digits: erf(x) ~ 2x / sqrt(pi).
    CHECK(erf_winitzki(1e-6f) == doctest::Approx(1.1283791670955126e-6).epsilon(1e-5));
}

TEST_CASE("Gaussian CDF with exact erf is 1 - erf(x) (Gumbau eq 7.4)") {
    const glm::vec2 m(0.5f, 0.25f + 0.01f);  // sigma = 0.1
    for (double x : {0.05, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0}) {
        const float z_r = float(0.5 + 0.1 * std::sqrt(2.0) * x);
        CAPTURE(x);
        const double expect = 1.0 - std::erf(x);
        CHECK(std::abs(gaussian_cdf_visibility(m, z_r, 0.0f, true) - expect) < 2e-6);  // erf plus float inputs
        CHECK(std::abs(gaussian_cdf_visibility(m, z_r, 0.0f, false) - expect) < 3.4e-4 + 2e-6);
    }
    // Gaussian vs Chebyshev: the Gaussian tail falls faster (less light bleeding).
    CHECK(gaussian_cdf_visibility(m, 0.8f, 0.0f, true) < chebyshev_upper_bound(m, 0.8f, 0.0f));
}

// ---------------------------------------------------------------------------------------------
namespace {
// Eq 7.6-7.7 in long double, written independently of the shader's evaluation.
long double power_cdf_reference(long double z_min, long double z_max, long double mean, long double z_r) {
    if (z_r <= mean) return 1.0L;
    if (z_r >= z_max) return 0.0L;
    const long double beta = (mean - z_min) / (z_max - mean);
    const long double t = (z_r - z_min) / (z_max - z_min);
    const long double t_mean = beta / (beta + 1.0L);
    return -std::expm1(beta * std::log(t)) / -std::expm1(beta * std::log(t_mean));
}
}  // namespace

TEST_CASE("power CDF: eq 7.7 at hand-computed points") {
    // beta = 1, t_mean = 1/2; z_r = 0.5 -> t = 3/4: (1 - 3/4) / (1 - 1/2) = 1/2.
    CHECK(power_cdf_visibility(0.2f, 0.6f, 0.4f, 0.5f) == doctest::Approx(0.5).epsilon(1e-5));
    // beta = 3, t_mean = 3/4; z_r = 0.9: (1 - 0.729) / (1 - 0.421875).
    CHECK(power_cdf_visibility(0.0f, 1.0f, 0.75f, 0.9f) == doctest::Approx(0.271 / 0.578125).epsilon(1e-5));
    // beta = 1/3, t_mean = 1/4; z_r = 0.3 -> t = 1/2: (1 - 2^(-1/3)) / (1 - 4^(-1/3)).
    CHECK(power_cdf_visibility(0.1f, 0.5f, 0.2f, 0.3f) ==
          doctest::Approx((1.0 - std::pow(0.5, 1.0 / 3.0)) / (1.0 - std::pow(0.25, 1.0 / 3.0))).epsilon(1e-5));
    CHECK(power_cdf_visibility(0.1f, 0.5f, 0.2f, 0.2f) == 1.0f);  // at the mean
    CHECK(power_cdf_visibility(0.1f, 0.5f, 0.2f, 0.5f) == 0.0f);  // at z_max
    // Against the long-double reference over random inputs.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
        float a = u(rng), b = u(rng);
        if (a > b) std::swap(a, b);
        const float mean = a + (b - a) * u(rng);
        const float z_r = u(rng);
        const long double expect = power_cdf_reference(a, b, mean, z_r);
        worst = std::max(worst, double(std::abs(power_cdf_visibility(a, b, mean, z_r) - expect)));
    }
    CHECK(worst < 2e-5);
}

TEST_CASE("power CDF: beta of eq 7.6 reproduces the mean") {
    // E[z] = z_max - integral of F over [z_min, z_max] = z_max - dz integral_0^1 t^beta dt.
    const float z_min = 0.2f, z_max = 0.7f;
    for (float mean : {0.2001f, 0.25f, 0.4f, 0.45f, 0.6f, 0.69f, 0.6999f}) {
        const double beta = (double(mean) - z_min) / (double(z_max) - mean);
        const int n = 200000;
        double integral = 0.0;  // midpoint rule on t^beta
        for (int i = 0; i < n; ++i) integral += std::pow((i + 0.5) / n, beta) / n;
        CAPTURE(mean);
        CHECK((z_max - (z_max - z_min) * integral) == doctest::Approx(mean).epsilon(1e-5));
        // The shader's curve at t_mean = beta / (beta + 1) is the mean itself: lit there.
        CHECK(power_cdf_visibility(z_min, z_max, mean, mean) == 1.0f);
    }
}

// The power-CDF lookup: each texel holds (min, max, mean) of its prefilter window. The lookup's
// mean blends the windows bilinearly; its min and max must bound every depth that mean averages,
// i.e. be the min and max over the windows of positive weight. A LINEAR lookup blends them too.
TEST_CASE("power CDF lookup: min and max over the blended texels, mean blended") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int blended_not_bounds = 0;
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 t[4];
        for (glm::vec3& texel : t) {  // a window: two depths and a weight between them
            const float a = u(rng), b = u(rng), w = u(rng);
            texel = {std::min(a, b), std::max(a, b), w * a + (1.0f - w) * b};
        }
        const glm::vec2 f(u(rng), u(rng));
        const glm::vec4 w = bilinear_weights(f);
        const glm::vec3 s = power_cdf_bilinear_statistics(t[0], t[1], t[2], t[3], f);
        CHECK(s.z == doctest::Approx(w.x * t[0].z + w.y * t[1].z + w.z * t[2].z + w.w * t[3].z).epsilon(1e-6));
        CHECK(s.x == std::min({t[0].x, t[1].x, t[2].x, t[3].x}));
        CHECK(s.y == std::max({t[0].y, t[1].y, t[2].y, t[3].y}));
        CHECK(s.x <= s.z);
        CHECK(s.z <= s.y);
        const float blended_min = w.x * t[0].x + w.y * t[1].x + w.z * t[2].x + w.w * t[3].x;
        blended_not_bounds += blended_min > s.x + 1e-3f;  // a receiver between them is misjudged
    }
    CHECK(blended_not_bounds > 1000);  // what a LINEAR lookup would do, for the record
    // At a texel centre (f = 0) the other texels have weight 0 and do not count.
    const glm::vec3 near_window(0.2f, 0.8f, 0.5f), far_window(0.9f, 0.9f, 0.9f);
    CHECK(power_cdf_bilinear_statistics(far_window, near_window, near_window, near_window, {0.0f, 0.0f}) == far_window);
    // Halfway across an occluder edge: a receiver at 0.85 sits between the near window's depths
    // and the far one's; with the bounds (0.2, 0.9) and mean 0.7 it is lit by
    // (1 - t^beta) / (1 - t_mu^beta), t = 0.65 / 0.7, beta = 0.5 / 0.2.
    const glm::vec3 s = power_cdf_bilinear_statistics(near_window, far_window, near_window, far_window, {0.5f, 0.5f});
    CHECK(s == glm::vec3(0.2f, 0.9f, 0.7f));
    const double beta = 2.5, t = 0.65 / 0.7, t_mu = beta / (beta + 1.0);
    CHECK(power_cdf_visibility(s.x, s.y, s.z, 0.85f) ==
          doctest::Approx((1.0 - std::pow(t, beta)) / (1.0 - std::pow(t_mu, beta))).epsilon(1e-4));
    // The price (README): a texel leaving the blend at weight 0 leaves the min with it, so the
    // reconstruction steps at texel centres. Window (0.5, 0.9, mean 0.7) beside one reaching 0.3:
    // at the centre beta = 1 and v(0.8) = 0.5; a hair off it z_min = 0.3, beta = 2, v = 0.55.
    const glm::vec3 own(0.5f, 0.9f, 0.7f), neighbour(0.3f, 0.9f, 0.6f);
    const glm::vec3 at_centre = power_cdf_bilinear_statistics(own, neighbour, own, neighbour, {0.0f, 0.0f});
    const glm::vec3 beside = power_cdf_bilinear_statistics(own, neighbour, own, neighbour, {1e-4f, 0.0f});
    const float v_centre = power_cdf_visibility(at_centre.x, at_centre.y, at_centre.z, 0.8f);
    const float v_beside = power_cdf_visibility(beside.x, beside.y, beside.z, 0.8f);
    CHECK(v_centre == doctest::Approx(0.5).epsilon(1e-4));
    CHECK(v_beside == doctest::Approx((1.0 - std::pow(0.5 / 0.6, 2.0)) / (1.0 - 4.0 / 9.0)).epsilon(1e-3));
    CHECK(v_beside - v_centre < 0.06f);
    // Extremes: inverted, infinite or huge texels and fractions outside [0, 1] stay finite and
    // in range once reconstructed.
    const float big = std::numeric_limits<float>::max();
    for (glm::vec3 odd : {glm::vec3(0.9f, 0.1f, 0.5f), glm::vec3(-kInf, kInf, 0.5f), glm::vec3(0.0f, big, big),
                          glm::vec3(-big, 0.0f, -big), glm::vec3(0.3f)}) {
        for (glm::vec2 f : {glm::vec2(0.0f), glm::vec2(1.0f), glm::vec2(0.5f), glm::vec2(-3.0f, 7.0f)}) {
            const glm::vec3 st = power_cdf_bilinear_statistics(odd, own, neighbour, odd, f);
            Sweep sweep{"power_cdf lookup of odd texels"};
            sweep.run(describe("mean", st.z), [&](float z_r) { return power_cdf_visibility(st.x, st.y, st.z, z_r); }, -1.0f,
                      0.0f, 0.0f);
            sweep.report(true, false);
        }
    }
}

TEST_CASE("power CDF limits: dz = 0, beta = 0, beta -> inf, inverted inputs") {
    // dz = 0: a clean step at the single depth.
    for (float z : {0.0f, 0.3f, 1.0f}) {
        CHECK(power_cdf_visibility(z, z, z, z) == 1.0f);
        CHECK(power_cdf_visibility(z, z, z, z - 1e-3f) == 1.0f);
        CHECK(power_cdf_visibility(z, z, z, std::nextafter(z, 2.0f)) == 0.0f);
    }
    // beta = 0 (mean = z_min): everything at z_min, so a receiver behind it is shadowed.
    CHECK(power_cdf_visibility(0.2f, 0.8f, 0.2f, 0.2f) == 1.0f);
    CHECK(power_cdf_visibility(0.2f, 0.8f, 0.2f, 0.2001f) == 0.0f);
    CHECK(power_cdf_visibility(0.0f, 1.0f, 0.0f, 1e-30f) == 0.0f);
    // beta -> 0: v = ln t / ln beta approximately, small but continuous.
    const float v_small = power_cdf_visibility(0.2f, 0.8f, 0.2f + 1e-6f, 0.5f);
    CHECK(v_small > 0.0f);
    CHECK(v_small < 0.1f);
    CHECK(v_small == doctest::Approx(double(power_cdf_reference(0.2L, 0.8L, 0.2L + 1e-6L, 0.5L))).epsilon(1e-2));
    // beta = inf (mean = z_max): no depth between mean and z_max.
    CHECK(power_cdf_visibility(0.2f, 0.8f, 0.8f, 0.8f) == 1.0f);
    CHECK(power_cdf_visibility(0.2f, 0.8f, 0.8f, 0.8001f) == 0.0f);
    // beta -> inf: the receiver halfway from the mean to z_max tends to (1 - e^-1/2) / (1 - e^-1).
    const float z_max = 0.75f, mean = 0.75f - 0x1p-20f, z_r = 0.75f - 0x1p-21f;
    const long double expect = power_cdf_reference(0.25L, z_max, mean, z_r);
    CHECK(power_cdf_visibility(0.25f, z_max, mean, z_r) == doctest::Approx(double(expect)).epsilon(1e-4));
    CHECK(expect == doctest::Approx((1.0 - std::exp(-0.5)) / (1.0 - std::exp(-1.0))).epsilon(1e-4));
    // The same where (z_r - z_min) / dz is not exact: ln t must come from z_max - z_r, not from
    // log of a ratio that rounds near 1 (that would be off by several per cent here).
    {
        const float lo = 0.1f, hi = 0.8f;
        const float ulp = std::nextafter(hi, 1.0f) - hi;
        const float m_near = hi - 16.0f * ulp;
        for (float steps : {1.0f, 3.0f, 8.0f, 13.0f, 15.0f}) {
            const float zr = hi - steps * ulp;
            CAPTURE(steps);
            CHECK(power_cdf_visibility(lo, hi, m_near, zr) == doctest::Approx(double(power_cdf_reference(lo, hi, m_near, zr))).epsilon(1e-4));
        }
    }
    // Inconsistent inputs (rounding, bad filtering) are repaired: a mean beyond z_max is z_max,
    // so a receiver behind z_max is shadowed; swapped bounds are swapped back.
    CHECK(power_cdf_visibility(0.2f, 0.8f, 0.9f, 0.85f) == 0.0f);
    CHECK(power_cdf_visibility(0.8f, 0.2f, 0.4f, 0.5f) == power_cdf_visibility(0.2f, 0.8f, 0.4f, 0.5f));
    CHECK(power_cdf_visibility(0.2f, 0.8f, 0.1f, 0.3f) == 0.0f);  // mean below z_min: beta = 0
    // They stay finite and in range.
    for (glm::vec3 s : {glm::vec3(0.8f, 0.2f, 0.5f), glm::vec3(0.2f, 0.8f, 0.9f), glm::vec3(0.2f, 0.8f, 0.1f),
                        glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 1e-38f, 5e-39f)}) {
        Sweep sweep{"power_cdf inconsistent"};
        sweep.run(describe("mean", s.z), [&](float z_r) { return power_cdf_visibility(s.x, s.y, s.z, z_r); }, -1.0f, 0.0f, 0.0f);
        sweep.report(true, false);
    }
}

// ---------------------------------------------------------------------------------------------
TEST_CASE("EVSM warps, exponent limits and single depths") {
    const glm::vec2 mid = evsm_warp(0.5f, 40.0f, 5.0f);
    CHECK(mid.x == 1.0f);
    CHECK(mid.y == -1.0f);
    CHECK(evsm_warp(1.0f, 3.0f, 2.0f).x == doctest::Approx(std::exp(3.0)));
    CHECK(evsm_warp(0.0f, 3.0f, 2.0f).y == doctest::Approx(-std::exp(2.0)));
    CHECK(evsm_warp(2.0f, 3.0f, 2.0f).x == evsm_warp(1.0f, 3.0f, 2.0f).x);  // z clamped to [0, 1]
    const glm::vec4 m = evsm_moments(0.8f, 4.0f, 3.0f);
    CHECK(m.y == doctest::Approx(m.x * m.x));
    CHECK(m.w == doctest::Approx(m.z * m.z));
    // Exponent limits: exp(c)^2 fits the storage at the limit and overflows past it.
    CHECK(evsm_max_exponent(true) == doctest::Approx(5.54f));
    CHECK(evsm_max_exponent(false) == doctest::Approx(42.0f));
    const glm::vec4 far16 = evsm_moments(1.0f, evsm_max_exponent(true), evsm_max_exponent(true));
    for (int i = 0; i < 4; ++i) CHECK(std::isfinite(half(far16[i])));
    CHECK(std::isinf(half(std::exp(2.0f * 5.6f))));
    const glm::vec4 far32 = evsm_moments(1.0f, 100.0f, 100.0f);  // clamped to 42
    for (int i = 0; i < 4; ++i) CHECK(std::isfinite(far32[i]));
    CHECK(std::isfinite(9.0f * far32.y));  // margin for filter sums

    // A single occluder depth: exactly 1 in front and at it; behind it only the min_variance floor
    // keeps the bound above 0.
    const float min_variance = 1e-5f;
    for (float z_o : {0.0f, 0.1f, 0.5f, 0.9f, 0.97f}) {
        for (glm::vec2 c : {glm::vec2(5.54f, 5.54f), glm::vec2(42.0f, 10.0f), glm::vec2(20.0f, 20.0f)}) {
            CAPTURE(z_o);
            CAPTURE(c.x);
            const glm::vec4 mo = evsm_moments(z_o, c.x, c.y);
            CHECK(evsm2_visibility({mo.x, mo.y}, z_o, c.x, min_variance) == 1.0f);
            CHECK(evsm4_visibility(mo, z_o, c.x, c.y, min_variance) == 1.0f);
            CHECK(evsm4_visibility(mo, z_o - 0.01f, c.x, c.y, min_variance) == 1.0f);
            // Behind by delta = 0.03: only the floor remains, k / (k + (1 - e^(-2 c delta))^2) with
            // k = (2c)^2 min_variance (the floor follows the warp's slope at the receiver).
            const float delta = 0.03f;
            const float v2 = evsm2_visibility({mo.x, mo.y}, z_o + delta, c.x, min_variance);
            const float v4 = evsm4_visibility(mo, z_o + delta, c.x, c.y, min_variance);
            const double k = 4.0 * double(c.x) * c.x * min_variance;
            const double gap = 1.0 - std::exp(-2.0 * c.x * (double(z_o + delta) - z_o));
            if (z_o + delta <= 1.0f) CHECK(v2 == doctest::Approx(k / (k + gap * gap)).epsilon(1e-3));
            CHECK(v2 < 0.08f);
            CHECK(v4 <= v2);
        }
    }
}

TEST_CASE("EVSM light bleeding is below VSM's for a two-depth mixture") {
    // Occluder edge: half at 0.2, half at 0.6; receiver at 0.7 is fully shadowed in truth.
    const Footprint f = mixture(0.2f, 0.6f, 0.5f);
    StatsOptions o;
    o.evsm_pos = 42.0f;
    o.evsm_neg = 10.0f;
    const Stats s = statistics(f, o);
    const float vsm = chebyshev_upper_bound(s.vsm, 0.7f, kMinVariance);
    const float evsm = evsm4_visibility(s.evsm, 0.7f, o.evsm_pos, o.evsm_neg, kMinVariance);
    CHECK(vsm == doctest::Approx(0.04 / (0.04 + 0.09)).epsilon(1e-4));  // heavy bleeding
    CHECK(evsm < 0.01f);
    // Receiver between the depths: half the footprint is in front, truth 0.5. The positive warp
    // alone sees the far depth's exp(42 z') dominate the mean and says lit (1); the negative warp
    // bounds it to about the truth, so EVSM4 gives ~0.5.
    CHECK(evsm2_visibility({s.evsm.x, s.evsm.y}, 0.4f, o.evsm_pos, kMinVariance) == 1.0f);
    CHECK(evsm4_visibility(s.evsm, 0.4f, o.evsm_pos, o.evsm_neg, kMinVariance) == doctest::Approx(0.5).epsilon(0.05));
}

// shadow.evsm's own exponents (c+ = 40, c- = 5; 5.54 for both in fp16) and min_variance, as its plan
// hands them to the shader. An edge -- weight w_a at z_a, the rest at z_b = z_a + 0.05 -- seen by a
// receiver at z_b: Chebyshev's bound of a two-point distribution at its far point is exactly the
// far point's weight, on any increasing warp, so EVSM must give 1 - w_a over the whole depth range.
// (The variance floors stay below that here.) Near the light the warped moments are tiny
// (E[p^2] ~ e^-80 at z = 0): a fixed floor of the bound's denominator used to take over there
// (0.21 instead of 0.5 for w_a = 1/2, z_a = 0).
TEST_CASE("EVSM at the technique's default exponents: an edge's lit fraction from z = 0 to z = 1") {
    // tolerance: against 1 - w_a; lit: how far from 1 a receiver in front may be (fp16 rounding).
    struct Precision { std::string name; std::function<float(float)> quantise; float tolerance; float lit; };
    for (const Precision& precision : {Precision{"fp32", [](float x) { return x; }, 1e-5f, 0.0f},
                                       Precision{"fp16", half, 0.02f, 1e-4f}}) {
        const canopy::ShadowPlan plan = plan_of("shadow.evsm", {{"precision", precision.name}});
        const auto block = plan.shader_params.get_block<canopy::shader::EvsmParams>();
        const float c_pos = block.c_pos, c_neg = block.c_neg;
        const float min_variance = block.min_variance;
        CAPTURE(precision.name);
        CAPTURE(c_pos);
        CAPTURE(c_neg);
        if (precision.name == "fp32") {
            CHECK(c_pos == 40.0f);  // the defaults this test is about
            CHECK(c_neg == 5.0f);
        }
        StatsOptions o;
        o.evsm_pos = c_pos;
        o.evsm_neg = c_neg;
        o.quantise = precision.quantise;
        const float delta = 0.05f;
        float worst4 = 0.0f, worst2 = 0.0f, worst_at = 0.0f;
        for (int i = 0; i <= 190; ++i) {
            const float z_a = std::min(float(i) / 200.0f, 1.0f - delta);  // 0, 0.005, ..., 0.95
            const float z_b = z_a + delta;
            for (float w_a : {0.25f, 0.5f, 0.75f}) {
                const Stats s = statistics(mixture(z_a, z_b, w_a), o);
                const float v4 = evsm4_visibility(s.evsm, z_b, c_pos, c_neg, min_variance);
                const float v2 = evsm2_visibility({s.evsm.x, s.evsm.y}, z_b, c_pos, min_variance);
                if (std::abs(v4 - (1.0f - w_a)) > worst4) worst_at = z_a;
                worst4 = std::max(worst4, std::abs(v4 - (1.0f - w_a)));
                worst2 = std::max(worst2, std::abs(v2 - (1.0f - w_a)));
                // In front of both depths: lit.
                CHECK(evsm4_visibility(s.evsm, std::max(z_a - 0.01f, 0.0f), c_pos, c_neg, min_variance) == 1.0f);
            }
        }
        MESSAGE(precision.name, ": EVSM4 worst |error| ", worst4, " (at z_a = ", worst_at, "), EVSM2 ", worst2);
        CHECK(worst4 <= precision.tolerance);
        CHECK(worst2 <= precision.tolerance);
        // The audit's example: half at 0, half at 0.05, receiver at 0.05.
        const Stats s = statistics(mixture(0.0f, delta, 0.5f), o);
        CHECK(evsm4_visibility(s.evsm, delta, c_pos, c_neg, min_variance) == doctest::Approx(0.5).epsilon(2.0 * precision.tolerance));

        // Every footprint at these exponents: finite, in [0, 1], non-increasing, lit in front.
        Sweep evsm4{"evsm4 defaults " + precision.name}, evsm2{"evsm2 defaults " + precision.name};
        for (const Footprint& f : footprints()) {
            const Stats st = statistics(f, o);
            const float front = footprint_min(f);
            evsm4.run(f.label, [&](float z) { return evsm4_visibility(st.evsm, z, c_pos, c_neg, min_variance); }, front,
                      precision.lit, 0.0f);
            evsm2.run(f.label, [&](float z) { return evsm2_visibility({st.evsm.x, st.evsm.y}, z, c_pos, min_variance); }, front,
                      precision.lit, 0.0f);
        }
        evsm4.report();
        evsm2.report();
    }
}

// ---------------------------------------------------------------------------------------------
TEST_CASE("MSM optimised quantisation round-trips and fits 16-bit storage") {
    double worst = 0.0;
    float lowest = 1.0f, highest = 0.0f;
    for (int i = 0; i <= 1000; ++i) {
        const float z = float(i) / 1000.0f;
        const glm::vec4 e = msm_encode(z);
        const glm::vec4 b = msm_decode(e);
        const glm::dvec4 exact(z, double(z) * z, double(z) * z * z, double(z) * z * z * z);
        for (int k = 0; k < 4; ++k) {
            worst = std::max(worst, std::abs(b[k] - exact[k]));
            lowest = std::min(lowest, e[k]);
            highest = std::max(highest, e[k]);
        }
    }
    MESSAGE("MSM encode range [", lowest, ", ", highest, "], fp32 round-trip max error ", worst);
    CHECK(worst < 1e-5);
    CHECK(lowest > -1e-5f);
    CHECK(highest < 1.0f + 1e-5f);
}

TEST_CASE("MSM Hamburger: single depths and two-depth mixtures") {
    struct Storage { const char* name; std::function<float(float)> quantise; float bias; float lit; float dark; };
    const std::vector<Storage> storages = {
        {"fp32", [](float x) { return x; }, kMsmBias32, 1e-4f, 0.05f},
        {"unorm16", unorm16, kMsmBias16, 1e-3f, 0.1f},
    };
    for (const Storage& st : storages) {
        StatsOptions o;
        o.quantise = st.quantise;
        for (float z_o : {0.0f, 0.05f, 0.3f, 0.5f, 0.8f, 0.95f, 1.0f}) {
            const Stats s = statistics(mixture(z_o, z_o, 1.0f), o);
            CAPTURE(st.name);
            CAPTURE(z_o);
            // Planar receiver: 1 - G with G <= alpha (see shadow_filtering.h).
            CHECK(msm_hamburger_visibility(s.msm, z_o, st.bias) >= 1.0f - st.lit);
            if (z_o >= 0.05f) CHECK(msm_hamburger_visibility(s.msm, z_o - 0.05f, st.bias) >= 1.0f - st.lit);
            if (z_o <= 0.95f) {
                const float behind = msm_hamburger_visibility(s.msm, z_o + 0.05f, st.bias);
                CHECK(behind <= st.dark);
            }
        }
        // A two-depth mixture: receiver between the depths sees the far depth's share of light.
        for (float w : {0.2f, 0.5f, 0.8f}) {
            const Stats s = statistics(mixture(0.2f, 0.6f, w), o);
            CAPTURE(st.name);
            CAPTURE(w);
            const float v = msm_hamburger_visibility(s.msm, 0.4f, st.bias);
            CHECK(v > 0.0f);
            CHECK(v < 1.0f);
            CHECK(v == doctest::Approx(1.0f - w).epsilon(0.05));
            CHECK(msm_hamburger_visibility(s.msm, 0.1f, st.bias) >= 1.0f - st.lit);
            CHECK(msm_hamburger_visibility(s.msm, 0.7f, st.bias) <= st.dark);
        }
    }
    // Degenerate and invalid moment vectors stay finite.
    for (glm::vec4 b : {glm::vec4(0.0f), glm::vec4(1.0f), glm::vec4(0.5f, 0.25f, 0.125f, 0.0625f), glm::vec4(0.5f),
                        glm::vec4(0.5f, 0.1f, 0.9f, 0.0f), glm::vec4(-1.0f, 2.0f, -3.0f, 4.0f)}) {
        for (float bias : {0.0f, 1e-9f, kMsmBias32, 1.0f}) {
            Sweep sweep{describe("msm invalid moments, bias", bias)};
            sweep.run(describe("b1", b.x), [&](float z_r) { return msm_hamburger_visibility(b, z_r, bias); }, -1.0f, 0.0f, 0.0f);
            sweep.report(false, false);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Every visibility over every footprint: finite, in [0, 1], non-increasing in z_r, lit in front.
TEST_CASE("all visibilities over depth distributions (fp32 statistics)") {
    StatsOptions o;
    Sweep cheb{"chebyshev"}, gauss_w{"gaussian winitzki"}, gauss_a{"gaussian accurate"}, power{"power_cdf"},
        esm{"esm"}, esm_log{"esm log"}, evsm2{"evsm2"}, evsm4{"evsm4"}, msm{"msm"}, bleed{"chebyshev + bleeding 0.3"};
    for (const Footprint& f : footprints()) {
        const Stats s = statistics(f, o);
        const float front = footprint_min(f);
        cheb.run(f.label, [&](float z) { return chebyshev_upper_bound(s.vsm, z, kMinVariance); }, std::min(front, s.vsm.x), 0.0f, 0.0f);
        bleed.run(f.label, [&](float z) { return reduce_light_bleeding(chebyshev_upper_bound(s.vsm, z, kMinVariance), 0.3f); },
                  std::min(front, s.vsm.x), 0.0f, 0.0f);
        gauss_w.run(f.label, [&](float z) { return gaussian_cdf_visibility(s.vsm, z, kMinVariance, false); }, std::min(front, s.vsm.x), 0.0f, 0.0f);
        gauss_a.run(f.label, [&](float z) { return gaussian_cdf_visibility(s.vsm, z, kMinVariance, true); }, std::min(front, s.vsm.x), 0.0f, 0.0f);
        power.run(f.label, [&](float z) { return power_cdf_visibility(s.z_min, s.z_max, s.mean, z); }, s.mean, 0.0f, 0.0f);
        esm.run(f.label, [&](float z) { return esm_visibility(s.esm_linear, z, o.esm_c); }, front, 1e-5f, 0.0f);
        esm_log.run(f.label, [&](float z) { return esm_visibility_log(s.esm_log, z, o.esm_c); }, front, 1e-5f, 0.0f);
        evsm2.run(f.label, [&](float z) { return evsm2_visibility({s.evsm.x, s.evsm.y}, z, o.evsm_pos, kMinVariance); }, front, 0.0f, 0.0f);
        evsm4.run(f.label, [&](float z) { return evsm4_visibility(s.evsm, z, o.evsm_pos, o.evsm_neg, kMinVariance); }, front, 0.0f, 0.0f);
        // MSM: lit up to the moment bias in front (G <= 0.686 alpha, plus rounding); the float
        // reconstruction may step back up (at this sweep's coarse steps < 4e-6; the dips just
        // behind an atom are measured by "MSM: measured rise" below).
        msm.run(f.label, [&](float z) { return msm_hamburger_visibility(s.msm, z, kMsmBias32); }, front, 1e-4f, 4e-6f);
    }
    for (const Sweep* s : {&cheb, &bleed, &gauss_w, &gauss_a, &power, &esm, &esm_log, &evsm2, &evsm4, &msm}) {
        CAPTURE(s->name);
        MESSAGE(s->name, ": worst step up ", s->worst_rise);
        s->report();
    }
}

// The same with every stored value rounded to half precision (an rgba16f map), over the full
// depth range: finite and in [0, 1] always; monotone where the function is monotone for any input.
TEST_CASE("all visibilities with 16-bit (half) statistics") {
    StatsOptions o;
    o.quantise = half;
    o.esm_c = 11.0f;  // exp(c) fits fp16
    o.evsm_pos = evsm_max_exponent(true);
    o.evsm_neg = evsm_max_exponent(true);
    Sweep cheb{"chebyshev fp16"}, gauss{"gaussian fp16"}, power{"power_cdf fp16"}, esm{"esm fp16"}, esm_log{"esm log fp16"},
        evsm4{"evsm4 fp16"}, msm{"msm fp16"};
    for (const Footprint& f : footprints()) {
        const Stats s = statistics(f, o);
        cheb.run(f.label, [&](float z) { return chebyshev_upper_bound(s.vsm, z, kMinVariance); }, -1.0f, 0.0f, 0.0f);
        gauss.run(f.label, [&](float z) { return gaussian_cdf_visibility(s.vsm, z, kMinVariance, true); }, -1.0f, 0.0f, 0.0f);
        power.run(f.label, [&](float z) { return power_cdf_visibility(s.z_min, s.z_max, s.mean, z); }, s.mean, 0.0f, 0.0f);
        esm.run(f.label, [&](float z) { return esm_visibility(s.esm_linear, z, o.esm_c); }, -1.0f, 0.0f, 0.0f);
        esm_log.run(f.label, [&](float z) { return esm_visibility_log(s.esm_log, z, o.esm_c); }, -1.0f, 0.0f, 0.0f);
        evsm4.run(f.label, [&](float z) { return evsm4_visibility(s.evsm, z, o.evsm_pos, o.evsm_neg, kMinVariance); }, -1.0f, 0.0f, 0.0f);
        msm.run(f.label, [&](float z) { return msm_hamburger_visibility(s.msm, z, kMsmBias16); }, -1.0f, 0.0f, 0.0f);
    }
    for (const Sweep* s : {&cheb, &gauss, &power, &esm, &esm_log, &evsm4}) {
        CAPTURE(s->name);
        s->report(true, s->name == "power_cdf fp16");
    }
    // MSM from half-float moments (possibly invalid after rounding): finite and in range only --
    // the reconstruction is not monotone there (see "MSM: measured rise"), hence unorm16 below.
    MESSAGE("msm fp16: worst step up ", msm.worst_rise);
    msm.report(false, false);
    // EVSM past the fp16 limit: the moments overflow to inf, the result must stay finite.
    StatsOptions over = o;
    over.evsm_pos = 10.0f;
    Sweep evsm_over{"evsm4 fp16 overflow c+ = 10"};
    for (const Footprint& f : footprints()) {
        const Stats s = statistics(f, over);
        evsm_over.run(f.label, [&](float z) { return evsm4_visibility(s.evsm, z, over.evsm_pos, over.evsm_neg, kMinVariance); }, -1.0f, 0.0f, 0.0f);
    }
    evsm_over.report(true, false);
}

// MSM's 64-bit variant as published: optimised moments in rgba16 unorm, alpha = 6e-5.
TEST_CASE("MSM with 16-bit unorm moments: monotone, lit in front") {
    StatsOptions o;
    o.quantise = unorm16;
    Sweep msm{"msm unorm16"};
    for (const Footprint& f : footprints()) {
        const Stats s = statistics(f, o);
        msm.run(f.label, [&](float z) { return msm_hamburger_visibility(s.msm, z, kMsmBias16); }, footprint_min(f) - 0.01f, 1e-3f, 4e-6f);
    }
    MESSAGE("msm unorm16: worst step up ", msm.worst_rise);
    msm.report();
}

// How far MSM's reconstruction rises with the receiver depth (it should never rise): the worst
// step up between consecutive receivers, over a coarse sweep of z_r (steps of 1/2048 over
// [-1.6 %, 101.6 %]) merged with a fine one (steps of 1e-5) from 5e-4 in front of to 2e-3 behind
// every depth of the footprint -- the rises are narrow dips just behind an atom, which a coarse
// sweep steps over. Footprints: the ones above plus 1200 random ones of the kinds that condition
// the Hankel matrix worst (close pairs, a far atom of tiny weight, clusters near z = 0 where z^4
// is tiny, equal-weight sets of up to 9 depths). Each storage at the moment bias it is documented
// with, 16-bit storage also at the technique's default; the bounds asserted are the ones
// shadow_filtering.h, SHADOW_FILTERING.md and the MSM README document, from this measurement.
TEST_CASE("MSM: measured rise with receiver depth, per storage, within the documented bounds") {
    std::vector<Footprint> set = footprints();
    std::mt19937 rng(2015);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int k = 0; k < 1200; ++k) {
        Footprint f;
        switch (k % 4) {
            case 0: {  // close pair
                const float z = u(rng);
                f = mixture(z, std::min(1.0f, z + 1e-3f * u(rng)), u(rng));
                break;
            }
            case 1: f = mixture(u(rng), u(rng), std::pow(u(rng), 6.0f)); break;  // a far atom of tiny weight
            case 2: {  // a cluster near the light and one more depth
                f.z = {0.1f * u(rng), 0.1f * u(rng), u(rng)};
                f.w = {u(rng) + 0.01f, u(rng) + 0.01f, u(rng) + 0.01f};
                const float total = f.w[0] + f.w[1] + f.w[2];
                for (float& w : f.w) w /= total;
                break;
            }
            default: {  // a box filter's equal weights
                const int n = 2 + k % 8;
                for (int i = 0; i < n; ++i) {
                    f.z.push_back(u(rng));
                    f.w.push_back(1.0f / float(n));
                }
            }
        }
        f.label = "random msm footprint " + std::to_string(k);
        set.push_back(f);
    }
    struct Storage { std::string name; std::function<float(float)> quantise; float bias; float documented_rise; };
    const std::vector<Storage> storages = {
        {"fp32, bias 3e-5 (default)", [](float x) { return x; }, kMsmBias32, 1e-4f},
        {"unorm16, bias 6e-5", unorm16, kMsmBias16, 1e-4f},
        {"unorm16, bias 3e-5 (default)", unorm16, kMsmBias32, 0.3f},
        {"fp16, bias 6e-5", half, kMsmBias16, 0.9f},
        {"fp16, bias 3e-5 (default)", half, kMsmBias32, 0.9f},
    };
    for (const Storage& st : storages) {
        StatsOptions o;
        o.quantise = st.quantise;
        float worst = 0.0f;
        std::string worst_where;
        int bad = 0;
        for (const Footprint& f : set) {
            const Stats s = statistics(f, o);
            std::vector<float> receivers;
            for (int i = -64; i <= 2048 + 64; ++i) receivers.push_back(float(i) / 2048.0f);
            for (float z : f.z)
                for (int i = -50; i <= 200; ++i) receivers.push_back(z + 1e-5f * float(i));
            std::sort(receivers.begin(), receivers.end());
            float previous = kInf;
            for (float z_r : receivers) {
                const float v = msm_hamburger_visibility(s.msm, z_r, st.bias);
                bad += !(std::isfinite(v) && v >= 0.0f && v <= 1.0f);
                if (v - previous > worst) {
                    worst = v - previous;
                    worst_where = f.label + describe(", z_r", z_r);
                }
                previous = v;
            }
        }
        CAPTURE(st.name);
        MESSAGE("msm ", st.name, ": worst step up ", worst, " (", worst_where, "); documented bound ", st.documented_rise);
        CHECK(bad == 0);
        CHECK(worst <= st.documented_rise);
    }
}

// G-F7.2 (Gumbau L1919, L1926, Fig. 7.2): with 16 bits per channel VSM and the Gaussian CDF show
// artifacts, the power CDF does not. What the functions actually do:
//  * a clean step (a flat occluder at z_o, receiver behind it by 0.01): the power CDF stores
//    (min, max, mean) = half(z_o) three times, dz = 0, and the result is the exact step 0. VSM and
//    the Gaussian CDF compute sigma^2 = E[z^2] - E[z]^2 from half-rounded values: the cancellation
//    leaves up to ~2.4e-4 of spurious variance (sigma ~ 0.015) near z = 1, so the receiver is lit
//    50-70 % -- the paper's 16-bit light leaking. With fp32 moments the same step stays dark;
//  * a planar receiver (its own occluder) is lit by all three once z_r carries a depth bias of the
//    storage's half-ulp (2^-12 below 1): the z_r <= mean test protects VSM and the Gaussian CDF
//    there too. Without that bias all three can fail where half(z) < z; the power CDF then
//    returns the step 0 (dz = 0), so it needs the bias as much as the others.
TEST_CASE("G-F7.2: 16-bit power CDF keeps a clean step, VSM and Gaussian CDF leak") {
    float worst_vsm16 = 0.0f, worst_gauss16 = 0.0f, worst_power16 = 0.0f, worst_vsm32 = 0.0f;
    float least_planar = 1.0f;
    const float bias16 = 0x1p-12f;
    for (int i = 0; i <= 400; ++i) {
        const float z_o = 0.5f + 0.49f * float(i) / 400.0f;
        StatsOptions o16;
        o16.quantise = half;
        const Stats s16 = statistics(mixture(z_o, z_o, 1.0f), o16);
        const Stats s32 = statistics(mixture(z_o, z_o, 1.0f), StatsOptions{});
        const float z_r = z_o + 0.01f;
        worst_vsm16 = std::max(worst_vsm16, chebyshev_upper_bound(s16.vsm, z_r, kMinVariance));
        worst_gauss16 = std::max(worst_gauss16, gaussian_cdf_visibility(s16.vsm, z_r, kMinVariance, true));
        worst_power16 = std::max(worst_power16, power_cdf_visibility(s16.z_min, s16.z_max, s16.mean, z_r));
        worst_vsm32 = std::max(worst_vsm32, chebyshev_upper_bound(s32.vsm, z_r, kMinVariance));
        // Planar receiver with the half-ulp bias: lit by all of them.
        const float planar = z_o - bias16;
        least_planar = std::min({least_planar, power_cdf_visibility(s16.z_min, s16.z_max, s16.mean, planar),
                                 chebyshev_upper_bound(s16.vsm, planar, kMinVariance),
                                 gaussian_cdf_visibility(s16.vsm, planar, kMinVariance, true)});
    }
    MESSAGE("clean step, receiver 0.01 behind: VSM16 lit ", worst_vsm16, ", Gaussian16 ", worst_gauss16,
            ", power16 ", worst_power16, ", VSM32 ", worst_vsm32);
    CHECK(worst_power16 == 0.0f);
    CHECK(worst_vsm16 > 0.5f);
    CHECK(worst_gauss16 > 0.4f);
    CHECK(worst_vsm32 < 0.011f);  // 1e-6 / (1e-6 + 1e-4): only the min_variance floor
    CHECK(least_planar == 1.0f);
    // A tilted planar receiver (depth gradient across a 9-tap footprint): the power CDF degrades
    // gracefully (it only sees where z_r falls between min and max), VSM's variance is noise.
    float least_power_tilted = 1.0f;
    for (int i = 0; i <= 100; ++i) {
        const float centre = 0.5f + 0.45f * float(i) / 100.0f;
        Footprint f;
        for (int k = -4; k <= 4; ++k) {
            f.z.push_back(centre + 5e-4f * float(k));
            f.w.push_back(1.0f / 9.0f);
        }
        StatsOptions o16;
        o16.quantise = half;
        const Stats s = statistics(f, o16);
        least_power_tilted = std::min(least_power_tilted, power_cdf_visibility(s.z_min, s.z_max, s.mean, centre - bias16));
    }
    CHECK(least_power_tilted == 1.0f);
}

// ---------------------------------------------------------------------------------------------
TEST_CASE("penumbra widths: eq 6.1 and 6.2 and their limits") {
    CHECK(pcss_penumbra_width(10.0f, 5.0f, 1.0f) == doctest::Approx(1.0f));
    CHECK(pcss_penumbra_width(10.0f, 2.0f, 0.5f) == doctest::Approx(2.0f));
    CHECK(ssss_screen_penumbra_width(10.0f, 5.0f, 1.0f, 4.0f) == doctest::Approx(0.25f));
    CHECK(pcss_penumbra_width(10.0f, 5.0f, 0.0f) == 0.0f);     // point light: hard shadow
    CHECK(pcss_penumbra_width(10.0f, 10.0f, 1.0f) == 0.0f);    // contact
    CHECK(pcss_penumbra_width(5.0f, 10.0f, 1.0f) == 0.0f);     // receiver in front of the "blocker"
    CHECK(pcss_penumbra_width(10.0f, 5.0f, -1.0f) == 0.0f);
    // Proportional to the light size (G-F6.9), finite for huge lights.
    CHECK(pcss_penumbra_width(10.0f, 5.0f, 4.0f) == doctest::Approx(4.0f * pcss_penumbra_width(10.0f, 5.0f, 1.0f)));
    for (float w_light : {1e6f, 1e20f, 1e30f, std::numeric_limits<float>::max()}) {
        for (float d_blocker : {5.0f, 1e-3f, 1e-30f, 0.0f, -1.0f}) {
            for (float d_observer : {1.0f, 1e-9f, 0.0f}) {
                const float p = pcss_penumbra_width(10.0f, d_blocker, w_light);
                const float s = ssss_screen_penumbra_width(10.0f, d_blocker, w_light, d_observer);
                CAPTURE(w_light);
                CAPTURE(d_blocker);
                CAPTURE(d_observer);
                CHECK_MESSAGE((std::isfinite(p) && p >= 0.0f), describe("pcss width", p));
                CHECK_MESSAGE((std::isfinite(s) && s >= 0.0f), describe("ssss width", s));
            }
        }
    }
    // d_blocker -> 0: capped at 1e6 light widths, growing monotonically towards the cap.
    float previous = 0.0f;
    for (float d_blocker = 5.0f; d_blocker > 1e-12f; d_blocker *= 0.5f) {
        const float p = pcss_penumbra_width(10.0f, d_blocker, 1.0f);
        CHECK(p >= previous);
        CHECK(p <= 1e6f * 1.0001f);
        previous = p;
    }
    CHECK(pcss_penumbra_width(0.0f, 0.0f, 1.0f) == 0.0f);
}
