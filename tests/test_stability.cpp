// `canopy bench stability`'s numbers (run/stability_bench.hpp) from recorded runs: within-run CV,
// run-to-run spread of each ratio, and which cases reach the targets.
#include "report/stability_report.hpp"
#include "run/group_measurement.hpp"
#include "run/stability_bench.hpp"

#include <doctest/doctest.h>

using namespace canopy;

namespace {

CaseResult measured(const std::string& id, std::vector<double> gpu, const std::vector<double>& baseline, bool is_baseline) {
    CaseResult c;
    c.id = id;
    c.scene = "spheres";
    c.technique = id;
    c.resolution = {640, 360};
    c.group_baseline = is_baseline;
    c.gpu_frame = {"gpu_frame", gpu, summarize(gpu)};
    c.cpu = c.gpu_frame;
    c.ratio = paired_ratio(gpu, baseline, id);
    return c;
}

// One run: a 10 ms baseline, "slow" at `ratio` x 10 ms (> 20 ms), "fast" at 1.5 x; `wobble`
// alternates the samples by +-wobble (relative).
RunRecord run_with(double ratio, double wobble = 0.0) {
    std::vector<double> base, slow, fast;
    for (int r = 0; r < 10; ++r) {
        const double w = r % 2 ? 1.0 + wobble : 1.0 - wobble;
        base.push_back(10.0);
        slow.push_back(10.0 * ratio * w);
        fast.push_back(15.0);
    }
    RunRecord run;
    run.experiment = "stability";
    run.identity.fields = {{"config_hash", "abc"}};
    run.rounds = 10;
    run.frames_per_sample = 1;
    run.cases = {measured("base", base, base, true), measured("slow", slow, base, false), measured("fast", fast, base, false)};
    return run;
}

}  // namespace

TEST_CASE("spread over runs and within-run CV, with the targets") {
    const StabilityResult r = analyse_stability({run_with(4.0), run_with(4.2), run_with(3.8, 0.1)});
    REQUIRE(r.cases.size() == 3);
    const CaseStability& base = r.cases[0];
    CHECK(base.group_baseline);
    CHECK_FALSE(base.spread_target_applies());
    const CaseStability& slow = r.cases[1];
    CHECK(slow.ratios.size() == 3);
    CHECK(slow.ratio_median == doctest::Approx(4.0));
    CHECK(slow.ratio_spread == doctest::Approx(0.4 / 4.0));  // (4.2 - 3.8) / 4.0
    CHECK(slow.ratio_cv == doctest::Approx(0.05));           // std of 4.0, 4.2, 3.8 = 0.2
    CHECK(slow.spread_target_applies());                     // 40 ms > 20 ms
    CHECK_FALSE(slow.meets_spread_target());
    CHECK(slow.within_cv_median == 0.0);
    CHECK(slow.within_cv_max > 0.09);  // the wobbling run
    CHECK(slow.meets_cv_target());     // the median run is still
    CHECK(slow.cpu_ratio_spread == doctest::Approx(slow.ratio_spread));
    const CaseStability& fast = r.cases[2];
    CHECK(fast.ratio_spread == 0.0);
    CHECK_FALSE(fast.spread_target_applies());  // 15 ms

    const std::string report = stability_markdown(r);
    CHECK(report.find("NOT reached") != std::string::npos);
    CHECK(report.find("n/a (under 20 ms)") != std::string::npos);
    CHECK(report.find("0 of 1 cases over 20 ms reach the spread target") != std::string::npos);
}

TEST_CASE("runs of different experiments or configs are refused") {
    RunRecord other = run_with(4.0);
    other.identity.fields = {{"config_hash", "def"}};
    CHECK_THROWS(analyse_stability({run_with(4.0), other}));
}
