// Pareto fronts (report/pareto.hpp): which configurations are dominated, with the time ratios'
// intervals and the metrics' tolerances deciding what is significant; pareto.md; the families'
// declared axes.
#include "core/registry.hpp"
#include "metrics/metric_registry.hpp"
#include "report/pareto.hpp"
#include "report/pareto_chart.hpp"
#include "report/pareto_report.hpp"
#include "run/block_bootstrap.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <stdexcept>

using namespace canopy;

namespace {

constexpr int kRounds = 30;

// A case of the run's one group whose per-round time ratio to the baseline is `ratio` times
// 1 + noise * sin(golden angle * round) (spread evenly over +-noise, the same in every case), with
// the given FLIP and PSNR.
CaseResult make_case(const std::string& id, double ratio, double noise, double flip, double psnr = 30.0) {
    CaseResult c;
    c.id = id;
    c.scene = "scene";
    c.technique = "shadow.pcf";
    c.resolution = {64, 64};
    for (int r = 0; r < kRounds; ++r) {
        const double wobble = 1.0 + noise * std::sin(2.39996 * r);
        c.ratio.per_round.push_back(ratio * wobble);
        c.gpu_frame.samples_ms.push_back(10.0 * ratio * wobble);
    }
    c.ratio.estimate = median_with_ci(c.ratio.per_round, bootstrap_seed(id));
    ImageMetrics m{};
    m.flip_mean = flip;
    m.psnr = psnr;
    c.image_error = m;
    return c;
}

RunRecord make_run(std::vector<CaseResult> cases) {
    RunRecord run;
    run.experiment = "pareto-test";
    GroupRecord group;
    group.name = "scene 64x64";
    group.scene = "scene";
    group.resolution = {64, 64};
    for (const CaseResult& c : cases) group.cases.push_back(c.id);
    run.groups.push_back(group);
    cases.front().group_baseline = true;
    run.cases = std::move(cases);
    return run;
}

// The (x, y) vertices of the chart's front line; empty when it draws none.
std::vector<std::pair<double, double>> front_line(const std::string& svg) {
    std::smatch line;
    if (!std::regex_search(svg, line, std::regex("<polyline class=\"front\" points=\"([^\"]*)\""))) return {};
    std::vector<std::pair<double, double>> vertices;
    const std::string points = line[1];
    const std::regex vertex("(-?[0-9.]+),(-?[0-9.]+)");
    for (auto it = std::sregex_iterator(points.begin(), points.end(), vertex); it != std::sregex_iterator(); ++it)
        vertices.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
    return vertices;
}

std::string chart(const ParetoFront& front) {
    return pareto_svg(front, *find_metric(front.metric), [](const CaseResult& c) { return c.id; });
}

const ParetoPoint& point(const ParetoFront& front, const std::string& id) {
    for (const ParetoPoint& p : front.points)
        if (p.result->id == id) return p;
    FAIL("no point " << id);
    throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("a configuration faster and no worse is dominant; slower and more accurate stays on the front") {
    const RunRecord run = make_run({
        make_case("base", 1.0, 0.0, 0.050),
        make_case("fast_and_good", 0.5, 0.01, 0.040),  // dominates base
        make_case("slow_and_best", 2.0, 0.01, 0.010),  // on the front
        make_case("slow_and_bad", 2.0, 0.01, 0.060),   // dominated by fast_and_good (and slow_and_best)
        make_case("fastest_worst", 0.3, 0.01, 0.200),  // on the front: nothing is faster
    });
    const std::vector<ParetoFront> fronts = pareto_fronts(run, "flip_mean");
    REQUIRE(fronts.size() == 1);
    const ParetoFront& front = fronts[0];
    CHECK(front.points.size() == 5);
    CHECK(point(front, "base").dominated);
    CHECK(point(front, "base").dominated_by == "fast_and_good");
    CHECK_FALSE(point(front, "fast_and_good").dominated);
    CHECK_FALSE(point(front, "slow_and_best").dominated);
    CHECK(point(front, "slow_and_bad").dominated);
    CHECK_FALSE(point(front, "fastest_worst").dominated);
    // The baseline's own ratio is exactly 1.
    CHECK(point(front, "base").time_ratio.value == 1.0);
}

TEST_CASE("differences within noise dominate nothing: a time inside the interval, an error inside the tolerance") {
    // Noisy rounds: 0.97 x the baseline's time, but the interval reaches past 1. Same FLIP within its
    // tolerance (1e-6 + 0.3 %).
    const RunRecord noisy = make_run({make_case("base", 1.0, 0.0, 0.0500), make_case("maybe_faster", 0.97, 0.2, 0.05001)});
    const ParetoFront front = pareto_fronts(noisy, "flip_mean")[0];
    REQUIRE(point(front, "maybe_faster").time_ratio.ci.high > 1.0);
    CHECK_FALSE(point(front, "base").dominated);
    CHECK_FALSE(point(front, "maybe_faster").dominated);

    // The same median time measured steadily: significantly faster, so it dominates.
    const RunRecord steady = make_run({make_case("base", 1.0, 0.0, 0.0500), make_case("faster", 0.97, 0.002, 0.05001)});
    const ParetoFront steady_front = pareto_fronts(steady, "flip_mean")[0];
    REQUIRE(point(steady_front, "faster").time_ratio.ci.high < 1.0);
    CHECK(point(steady_front, "base").dominated);

    // Equal time within noise, error lower by far more than the tolerance: dominates.
    const RunRecord better = make_run({make_case("base", 1.0, 0.0, 0.0500), make_case("better", 1.01, 0.2, 0.030)});
    CHECK(point(pareto_fronts(better, "flip_mean")[0], "base").dominated);
    // A slightly lower error inside the tolerance: does not.
    const RunRecord same = make_run({make_case("base", 1.0, 0.0, 0.0500), make_case("same", 1.01, 0.2, 0.04999)});
    CHECK_FALSE(point(pareto_fronts(same, "flip_mean")[0], "base").dominated);
}

TEST_CASE("a significantly slower configuration dominates nothing, however small its error") {
    const RunRecord run = make_run({make_case("base", 1.0, 0.0, 0.05), make_case("slow_exact", 1.2, 0.01, 0.0)});
    const ParetoFront front = pareto_fronts(run, "flip_mean")[0];
    CHECK_FALSE(point(front, "base").dominated);
    CHECK_FALSE(point(front, "slow_exact").dominated);
}

TEST_CASE("a metric where higher is better is compared that way (PSNR)") {
    const RunRecord run = make_run({make_case("base", 1.0, 0.0, 0.05, 30.0), make_case("fast_sharp", 0.5, 0.01, 0.05, 40.0),
                                    make_case("fast_blurry", 0.5, 0.01, 0.05, 20.0)});
    const ParetoFront front = pareto_fronts(run, "psnr_db")[0];
    CHECK(point(front, "base").dominated);
    CHECK(point(front, "base").dominated_by == "fast_sharp");
    CHECK(point(front, "fast_blurry").dominated);
    CHECK_FALSE(point(front, "fast_sharp").dominated);
}

TEST_CASE("cases without the metric or a time are listed apart; an unknown metric is refused") {
    std::vector<CaseResult> cases{make_case("base", 1.0, 0.0, 0.05), make_case("no_error", 0.5, 0.01, 0.05),
                                  make_case("failed", 0.5, 0.01, 0.05)};
    cases[1].image_error.reset();
    cases[2].ok = false;
    const RunRecord run = make_run(cases);
    const ParetoFront front = pareto_fronts(run, "flip_mean")[0];
    CHECK(front.points.size() == 1);
    CHECK(front.unmeasured == std::vector<std::string>{"no_error"});
    // visibility_rmse's group is not declared by these cases (ErrorColumns{}): n/a, not on the chart.
    CHECK(pareto_fronts(run, "visibility_rmse")[0].points.empty());
    CHECK_THROWS_AS(pareto_fronts(run, "flip"), std::invalid_argument);  // a claim name, not a results.json name
}

TEST_CASE("the chart's front line is a staircase that never turns back, through the undominated points") {
    // Undominated by time: base (0.050), within_noise (slower within noise, worse in error within
    // FLIP's tolerance: undominated, yet no better than base), slow_best (0.010). A line joining them
    // in time order would zig-zag.
    const RunRecord run = make_run({make_case("base", 1.0, 0.0, 0.050), make_case("within_noise", 1.02, 0.2, 0.05010),
                                    make_case("slow_best", 2.0, 0.01, 0.010), make_case("slow_bad", 2.0, 0.01, 0.080)});
    const ParetoFront front = pareto_fronts(run, "flip_mean")[0];
    REQUIRE(front.judged);
    REQUIRE_FALSE(point(front, "within_noise").dominated);
    REQUIRE(point(front, "slow_bad").dominated);
    const std::vector<std::pair<double, double>> line = front_line(chart(front));
    REQUIRE(line.size() == 3);  // base, the corner below it at slow_best's time, slow_best
    for (size_t i = 1; i < line.size(); ++i) {
        CHECK(line[i].first >= line[i - 1].first);    // rightwards: slower
        CHECK(line[i].second >= line[i - 1].second);  // downwards on the page: lower error
    }
}

TEST_CASE("a --quick run judges nothing dominated, says why, and draws no front line") {
    std::vector<CaseResult> cases{make_case("base", 1.0, 0.0, 0.050), make_case("fast_and_good", 0.5, 0.01, 0.040),
                                  make_case("slow_and_worse", 2.0, 0.01, 0.060)};
    for (CaseResult& c : cases) c.ratio.per_round.resize(3);
    RunRecord run = make_run(cases);
    run.rounds = 3;
    run.quick = true;
    const ParetoFront front = pareto_fronts(run, "flip_mean")[0];
    CHECK_FALSE(front.judged);
    for (const ParetoPoint& p : front.points) CHECK_FALSE(p.dominated);
    const std::string note = too_few_rounds_note(run);
    CHECK(note.find("--quick: 3 rounds, fewer than the 6 a paired time interval needs") == 0);
    CHECK(note.find("none is judged dominated") != std::string::npos);
    CHECK(pareto_report(run, {"flip_mean"}).find(note) != std::string::npos);
    const std::string svg = chart(front);
    CHECK(svg.find("<polyline") == std::string::npos);
    CHECK(svg.find("<circle") != std::string::npos);
    // With its rounds: judged, and a line.
    run.rounds = kRounds;
    CHECK(too_few_rounds_note(run).empty());
    CHECK(front_line(chart(pareto_fronts(make_run({make_case("base", 1.0, 0.0, 0.050), make_case("fast_and_good", 0.5, 0.01, 0.040),
                                                   make_case("slow_best", 2.0, 0.01, 0.010)}),
                                         "flip_mean")[0]))
              .size() == 3);
}

// The horizontal position of case `id`'s point in a chart.
double point_x(const std::string& svg, const std::string& id) {
    std::smatch circle;
    REQUIRE(std::regex_search(svg, circle, std::regex("data-case=\"" + id + "\" cx=\"([0-9.]+)\"")));
    return std::stod(circle[1]);
}

TEST_CASE("an axis whose positive values span a factor of 20 or more is logarithmic") {
    CHECK(log_axis(0.02, 1.0));
    CHECK(log_axis(0.05, 1.0));  // exactly kLogAxisSpan
    CHECK_FALSE(log_axis(0.06, 1.0));
    CHECK_FALSE(log_axis(1.0, 2.8));
    CHECK_FALSE(log_axis(0.0, 1.0));  // an exact zero has no logarithm
    CHECK_FALSE(log_axis(-0.5, 1.0));

    // Grass's impostors at 0.02 to 0.5 x the geometry's time: equal factors, equal distances.
    const RunRecord grass = make_run({make_case("base", 1.0, 0.0, 0.05), make_case("impostor", 0.02, 0.01, 0.14),
                                      make_case("volume", 0.1, 0.01, 0.10), make_case("lod", 0.5, 0.01, 0.06)});
    const std::string svg = chart(pareto_fronts(grass, "flip_mean")[0]);
    CHECK(svg.find("95 % interval; log scale)") != std::string::npos);
    CHECK(svg.find("lower is better)") != std::string::npos);  // FLIP spans 0.05 to 0.14: linear
    const double to_volume = point_x(svg, "volume") - point_x(svg, "impostor"), to_lod = point_x(svg, "lod") - point_x(svg, "volume");
    CHECK(to_volume == doctest::Approx(to_lod).epsilon(0.01));
    for (const char* tick : {">0.02</text>", ">0.05</text>", ">0.10</text>", ">0.20</text>", ">0.50</text>", ">1.00</text>"})
        CHECK_MESSAGE(svg.find(tick) != std::string::npos, tick);

    // Times within a factor of 3: linear.
    const RunRecord shadows = make_run({make_case("base", 1.0, 0.0, 0.05), make_case("pcf", 2.8, 0.01, 0.03)});
    CHECK(chart(pareto_fronts(shadows, "flip_mean")[0]).find("log scale") == std::string::npos);
}

TEST_CASE("every point of a chart is numbered in the SVG itself, its numbers apart from each other") {
    // Three points almost on top of each other, as grass's impostors are, and one apart.
    const RunRecord run = make_run({make_case("base", 1.0, 0.0, 0.050), make_case("a", 0.500, 0.01, 0.0800),
                                    make_case("b", 0.502, 0.01, 0.0801), make_case("c", 0.504, 0.01, 0.0802)});
    const std::string svg = chart(pareto_fronts(run, "flip_mean")[0]);
    const std::regex number("<text class=\"point-label\" x=\"([0-9.]+)\" y=\"([0-9.]+)\" font-size=\"10\">([0-9]+)</text>");
    std::vector<std::pair<double, double>> places;
    std::string numbers;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), number); it != std::sregex_iterator(); ++it) {
        places.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
        numbers += (*it)[3].str();
    }
    CHECK(numbers == "1234");  // the order of front.points: the table's rows
    for (size_t i = 0; i < places.size(); ++i)
        for (size_t j = 0; j < i; ++j) {
            CAPTURE(i);
            CAPTURE(j);
            CHECK((std::abs(places[i].first - places[j].first) >= 6 || std::abs(places[i].second - places[j].second) >= 9));
        }
    CHECK(svg.find("<title>2. a: time 0.50") != std::string::npos);  // the tooltip names it, numbered too
}

TEST_CASE("pareto.md marks the front, names a dominating configuration and sorts by time") {
    const RunRecord run = make_run({make_case("base", 1.0, 0.0, 0.050), make_case("fast_and_good", 0.5, 0.01, 0.040),
                                    make_case("slow_and_best", 2.0, 0.01, 0.010)});
    const std::string text = pareto_report(run, {"flip_mean"});
    CHECK(text.find("# Pareto fronts — pareto-test") != std::string::npos);
    CHECK(text.find("## scene 64x64 — FLIP (lower is better)\n") != std::string::npos);  // FLIP has no unit
    CHECK(pareto_report(run, {"rmse"}).find("## scene 64x64 — RMSE (linear RGB, lower is better)\n") != std::string::npos);
    const size_t fast = text.find("| front | shadow.pcf"), base = text.find("|       | shadow.pcf");
    REQUIRE(fast != std::string::npos);
    REQUIRE(base != std::string::npos);
    CHECK(fast < base);  // 0.5 before 1.0
    CHECK(text.find("0.50 [") != std::string::npos);
    CHECK(pareto_report(RunRecord{}, {"flip_mean"}).empty());
}

TEST_CASE("pareto.md names a dominating configuration without parameters by its technique alone") {
    std::vector<CaseResult> cases{make_case("base", 1.0, 0.0, 0.050), make_case("fast_and_good", 0.5, 0.01, 0.040)};
    cases[1].technique = "shadow.hard";
    cases[1].params_shown = "-";  // no parameter shown
    const std::string text = pareto_report(make_run(cases), {"flip_mean"});
    CHECK(text.find("| shadow.hard  |\n") != std::string::npos);  // base's "dominated by"
    CHECK(text.find("shadow.hard -") == std::string::npos);
}

TEST_CASE("every technique's declared Pareto axes are registered metrics of groups it declares") {
    for (const Technique* technique : TechniqueRegistry::instance().all()) {
        CAPTURE(technique->name());
        const std::vector<std::string> axes = technique->pareto_errors();
        CHECK_FALSE(axes.empty());
        for (const std::string& axis : axes) {
            CAPTURE(axis);
            const MetricInfo* metric = find_metric(axis);
            REQUIRE(metric != nullptr);
            CHECK(group_declared(metric->group, technique->error_columns()));
        }
    }
    // The families' choices (issue 11): the shadow's isolated error and penumbra error; grass's
    // whole-image and coverage errors.
    CHECK(TechniqueRegistry::instance().find("shadow.pcss")->pareto_errors() ==
          std::vector<std::string>{"visibility_rmse", "penumbra_rmse"});
    CHECK(TechniqueRegistry::instance().find("grass.volume")->pareto_errors() ==
          std::vector<std::string>{"flip_mean", "rmse", "coverage_tile_mae"});
}
