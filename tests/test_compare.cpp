// `canopy compare` on recorded samples (run/run_comparison.hpp): synthetic per-round ratios with a
// known shift must be flagged, the same ratios with fresh noise and no shift must not, and the
// bookkeeping around them (one-sided cases, refusals, error tolerances) must say what happened.
#include "metrics/metric_registry.hpp"
#include "report/comparison_report.hpp"
#include "run/run_comparison.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace canopy;

namespace {

// Noisy per-round values around `centre`: independent uniform noise of +-`spread` (relative)
// plus a slow level that carries over between rounds, as load shifts do.
std::vector<double> rounds_around(double centre, double spread, uint64_t seed, size_t rounds = 20) {
    SplitMix64 random(seed);
    std::vector<double> v;
    double level = 0.0;
    for (size_t r = 0; r < rounds; ++r) {
        const double u = double(random.next() >> 11) * 0x1.0p-53 - 0.5;
        level = 0.5 * level + 0.5 * u;
        v.push_back(centre * (1.0 + spread * (u + level)));
    }
    return v;
}

CaseResult timed_case(const std::string& id, std::vector<double> ratios, bool baseline = false) {
    CaseResult c;
    c.id = id;
    c.scene = "spheres";
    c.technique = baseline ? "shadow.hard" : "shadow.pcf";
    c.resolution = {320, 180};
    c.group_baseline = baseline;
    // GPU samples: a baseline of about 10 ms times the ratio of each round.
    for (size_t r = 0; r < ratios.size(); ++r) c.gpu_frame.samples_ms.push_back(10.0 * ratios[r]);
    c.gpu_frame.stats = summarize(c.gpu_frame.samples_ms);
    c.ratio.per_round = std::move(ratios);
    c.ratio.estimate = median_with_ci(c.ratio.per_round, bootstrap_seed(id));
    ImageMetrics m{};
    m.mae = 0.01;
    m.rmse = 0.02;
    m.psnr = 34.0;
    m.ssim = 0.98;
    m.flip_mean = 0.05;
    m.light_bleeding = 0.003;
    m.over_darkening = 0.002;
    m.penumbra_rmse = 0.04;
    c.image_error = m;
    return c;
}

RunRecord run_of(std::vector<CaseResult> cases, const std::string& commit = "aaaa") {
    RunRecord run;
    run.experiment = "quick-suite";
    run.identity.fields = {{"experiment", "quick-suite"}, {"config_hash", "0123"}, {"commit", commit}, {"device", "llvmpipe"}};
    run.rounds = 20;
    run.frames_per_sample = 1;
    run.cases = std::move(cases);
    return run;
}

// Baseline case + 3 cases with ratios 2, 4 and 8, each with 3 % noise; `shift` multiplies the
// ratios of "pcf_b".
RunRecord suite(uint64_t seed, double shift = 1.0, const std::string& commit = "aaaa") {
    return run_of({timed_case("hard", std::vector<double>(20, 1.0), true),
                   timed_case("pcf_a", rounds_around(2.0, 0.06, seed + 1)),
                   timed_case("pcf_b", rounds_around(4.0 * shift, 0.06, seed + 2)),
                   timed_case("pcf_c", rounds_around(8.0, 0.06, seed + 3))},
                  commit);
}

const CaseComparison& find(const RunComparison& c, const std::string& id) {
    for (const CaseComparison& cc : c.cases)
        if (cc.id == id) return cc;
    FAIL("no case " << id);
    return c.cases.front();
}

}  // namespace

TEST_CASE("an unchanged rerun is not flagged, whatever its noise") {
    // 50 reruns with fresh noise: no case is ever flagged as a regression.
    for (uint64_t seed = 0; seed < 50; ++seed) {
        const RunComparison c = compare_runs(suite(1000), suite(2000 + 10 * seed), {});
        CAPTURE(seed);
        CHECK(c.regressions() == 0);
        CHECK(c.passed());
    }
}

TEST_CASE("a known slowdown is flagged with an interval around it; an improvement is reported, not flagged") {
    const RunComparison slower = compare_runs(suite(1000), suite(2000, 1.20), {});  // pcf_b 20 % slower
    const CaseComparison& b = find(slower, "pcf_b");
    CHECK(b.time.verdict == TimeVerdict::regression);
    CHECK(b.time.change.value == doctest::Approx(0.20).epsilon(0.2));
    CHECK(b.time.change.ci.low > 0.05);
    CHECK(b.time.change.ci.low < 0.20);
    CHECK(b.time.change.ci.high > 0.20);
    CHECK(find(slower, "pcf_a").time.verdict != TimeVerdict::regression);
    CHECK(find(slower, "hard").time.verdict == TimeVerdict::baseline);
    CHECK(slower.regressions() == 1);
    CHECK_FALSE(slower.passed());

    const RunComparison faster = compare_runs(suite(1000), suite(2000, 0.80), {});
    CHECK(find(faster, "pcf_b").time.verdict == TimeVerdict::improvement);
    CHECK(faster.improvements() == 1);
    CHECK(faster.passed());

    // A 4 % slowdown is below a 5 % threshold: never flagged.
    const RunComparison small = compare_runs(suite(1000), suite(2000, 1.04), {});
    CHECK(find(small, "pcf_b").time.verdict != TimeVerdict::regression);
    // The threshold decides: at 30 %, the 20 % slowdown is not flagged either.
    ComparisonSettings lenient;
    lenient.threshold = 0.30;
    CHECK(compare_runs(suite(1000), suite(2000, 1.20), lenient).regressions() == 0);
}

TEST_CASE("noise that reaches past the threshold is inconclusive, not flagged") {
    // 7 % slower with 40 % noise: the interval covers both sides of +5 %.
    RunRecord before = run_of({timed_case("hard", std::vector<double>(20, 1.0), true), timed_case("x", rounds_around(4.0, 0.8, 1))});
    RunRecord after = run_of({timed_case("hard", std::vector<double>(20, 1.0), true), timed_case("x", rounds_around(4.28, 0.8, 2))});
    const RunComparison c = compare_runs(before, after, {});
    CHECK(find(c, "x").time.verdict == TimeVerdict::inconclusive);
    CHECK(c.passed());
}

TEST_CASE("too few rounds judge no time change") {
    RunRecord before = run_of({timed_case("x", rounds_around(4.0, 0.01, 1, 3))});
    RunRecord after = run_of({timed_case("x", rounds_around(8.0, 0.01, 2, 3))});
    const RunComparison c = compare_runs(before, after, {});
    CHECK(find(c, "x").time.verdict == TimeVerdict::too_few_rounds);
    CHECK(c.passed());
}

TEST_CASE("cases on one side only are listed, failures are named, and a new failure is flagged") {
    RunRecord before = suite(1000);
    RunRecord after = suite(2000);
    after.cases.erase(after.cases.begin() + 1);  // pcf_a gone
    after.cases.push_back(timed_case("pcf_new", rounds_around(3.0, 0.06, 7)));
    after.cases[1].ok = false;  // pcf_b now fails
    after.cases[1].error = "12 pixels are NaN or Inf";
    const RunComparison c = compare_runs(before, after, {});
    CHECK(c.only_in_baseline == std::vector<std::string>{"pcf_a"});
    CHECK(c.only_in_candidate == std::vector<std::string>{"pcf_new"});
    CHECK(find(c, "pcf_b").failed_candidate);
    CHECK(c.newly_failed() == 1);
    CHECK_FALSE(c.passed());
    const std::string report = comparison_report({"a", &before}, {"b", &after}, c);
    CHECK(report.find("only in the baseline: pcf_a") != std::string::npos);
    CHECK(report.find("only in the candidate: pcf_new") != std::string::npos);
    CHECK(report.find("FAILED (candidate)") != std::string::npos);
    CHECK(report.find("exit code 1") != std::string::npos);
}

TEST_CASE("runs of other experiments or configs are refused; other commits are compared and named") {
    RunRecord other = suite(1);
    other.experiment = "default";
    CHECK_THROWS_AS(compare_runs(suite(1), other, {}), ComparisonRefused);
    RunRecord changed = suite(1);
    changed.identity.fields[1].second = "4567";
    CHECK_THROWS_WITH_AS(compare_runs(suite(1), changed, {}), doctest::Contains("different configs"), ComparisonRefused);

    const RunRecord before = suite(1000), after = suite(2000, 1.0, "bbbb");
    const RunComparison c = compare_runs(before, after, {});
    REQUIRE(c.differences.size() == 1);
    CHECK(c.differences[0] == "commit: aaaa -> bbbb");
    const std::string report = comparison_report({"a", &before}, {"b", &after}, c);
    CHECK(report.find("commit: aaaa -> bbbb") != std::string::npos);
    CHECK(report.find("exit code 0") != std::string::npos);
}

TEST_CASE("error metrics: within tolerance passes, beyond it is flagged; NaN only matches NaN") {
    RunRecord before = suite(1000), after = suite(2000);
    const MetricInfo* rmse = find_metric("rmse");
    REQUIRE(rmse);
    const double allowed = rmse->tolerance.absolute + rmse->tolerance.relative * 0.02;
    after.cases[2].image_error->rmse = 0.02 + 0.5 * allowed;
    CHECK(compare_runs(before, after, {}).passed());
    after.cases[2].image_error->rmse = 0.02 + 2.0 * allowed;
    RunComparison c = compare_runs(before, after, {});
    CHECK(c.errors_out_of_tolerance() == 1);
    CHECK_FALSE(c.passed());
    CHECK(comparison_report({"a", &before}, {"b", &after}, c).find("Error metrics out of tolerance") != std::string::npos);
    ComparisonSettings time_only;
    time_only.errors = false;
    CHECK(compare_runs(before, after, time_only).passed());

    after = suite(2000);
    before.cases[1].image_error->light_bleeding = after.cases[1].image_error->light_bleeding = std::nan("");
    CHECK(compare_runs(before, after, {}).passed());  // not applicable in both
    after.cases[1].image_error->light_bleeding = 0.003;
    CHECK_FALSE(compare_runs(before, after, {}).passed());
}
