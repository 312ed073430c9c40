// The per-case columns of results.csv and results.md come from one list (report/result_columns.hpp):
// every row has a cell under every header, families expand to the run's passes and the registered
// metrics, and a column declared there reaches both reports with nothing else to edit.
#include "metrics/metric_registry.hpp"
#include "report/csv_report.hpp"
#include "report/markdown_report.hpp"
#include "report/pareto.hpp"
#include "report/result_columns.hpp"
#include "run/block_bootstrap.hpp"

#include <doctest/doctest.h>

#include <sstream>
#include <string>

using namespace canopy;

namespace {

TimingSeries series(std::string name, double median) {
    TimingSeries t;
    t.name = std::move(name);
    t.samples_ms = {median, median};
    t.stats.count = 2;
    t.stats.median = t.stats.mean = t.stats.min = t.stats.max = median;
    return t;
}

CaseResult timed_case(const std::string& id, std::vector<std::string> gpu_passes, std::vector<std::string> cpu_passes) {
    CaseResult c;
    c.id = id;
    c.scene = "spheres";
    c.technique = "shadow.hard";
    c.resolution = {96, 64};
    c.gpu_frame = series("gpu_frame", 2.5);
    c.wall = series("wall", 2.75);
    c.record_cpu = series("record_cpu", 0.0625);
    for (const std::string& p : gpu_passes) c.passes.push_back(series(p, 1.25));
    for (const std::string& p : cpu_passes) c.cpu_passes.push_back(series(p, 0.5));
    c.timing_check = check_pass_timing({{1.25, 1.25}}, {2.75, 2.75});
    return c;
}

RunRecord run_of_two() {
    RunRecord run;
    run.frames_per_sample = 1;
    run.environment.device.name = "llvmpipe";
    run.environment.git_commit = "abc";
    run.cases.push_back(timed_case("a", {"shadow_map", "lit"}, {}));
    run.cases.push_back(timed_case("b", {"cull", "lit"}, {"lod_select"}));
    run.cases.back().load = {{{"bake", 3.5}}, 3.5, 4.25, 1024};
    return run;
}

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, separator)) cells.push_back(cell);
    if (!line.empty() && line.back() == separator) cells.emplace_back();
    return cells;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

}  // namespace

TEST_CASE("every column gives as many cells as headers, for every case") {
    const RunRecord run = run_of_two();
    for (const ResultColumn& column : result_columns()) {
        CAPTURE(column.name);
        REQUIRE(column.csv);
        const auto csv = column.csv(run);
        REQUIRE(csv.cells);
        for (const CaseResult& c : run.cases) {
            CHECK(csv.cells(c).size() == csv.headers.size());
            if (!column.markdown) continue;
            const auto markdown = column.markdown(run);
            REQUIRE(markdown.cells);
            CHECK(markdown.cells(c).size() == markdown.headers.size());
        }
    }
}

TEST_CASE("results.csv: one cell under every header, pass families per name the run holds") {
    const auto rows = lines(csv_report(run_of_two()));
    REQUIRE(rows.size() == 3);
    const std::vector<std::string> header = split(rows[0], ',');
    for (size_t r = 1; r < rows.size(); ++r) CHECK(split(rows[r], ',').size() == header.size());
    const auto column = [&](const std::string& name) {
        for (size_t i = 0; i < header.size(); ++i)
            if (header[i] == name) return int(i);
        return -1;
    };
    // The layout before the list existed, kept: scripts that index columns still read them.
    CHECK(rows[0].rfind("id,scene,technique,params,width,height,ok,gpu_ms_median,gpu_ms_min,gpu_ms_mean,gpu_ms_mad,gpu_cv,"
                        "wall_ms_median,wall_ms_mad,wall_cv,cpu_ms_median,ratio,ratio_ci95_low,ratio_ci95_high,rounds,"
                        "frames_per_sample,shadow_map_gpu_ms_median,shadow_map_gpu_ms_mad,lit_gpu_ms_median,",
                        0) == 0);
    for (const char* name : {"cull_gpu_ms_median", "lod_select_cpu_ms_median", "record_cpu_ms_median",
                             "timing_check_gap_ms", "timing_check_agrees", "technique_memory_bytes", "device", "commit"})
        CHECK_MESSAGE(column(name) >= 0, name);
    for (const MetricInfo& metric : registered_metrics()) CHECK(column(std::string(metric.name)) >= 0);
    const std::vector<std::string> a = split(rows[1], ','), b = split(rows[2], ',');
    CHECK(a[size_t(column("cull_gpu_ms_median"))].empty());  // case a has no such pass
    CHECK(b[size_t(column("cull_gpu_ms_median"))] == "1.25");
    CHECK(b[size_t(column("lod_select_cpu_ms_median"))] == "0.5");
    CHECK(b[size_t(column("record_cpu_ms_median"))] == "0.0625");
    CHECK(b[size_t(column("timing_check_gap_ms"))] == "1.5");  // 2.75 - 1.25: beyond 0.5 ms
    CHECK(b[size_t(column("timing_check_agrees"))] == "0");
    CHECK(a[size_t(column("load_gpu_ms"))].empty());  // case a has no load phase
    CHECK(b[size_t(column("load_gpu_ms"))] == "3.5");
    CHECK(b[size_t(column("load_wall_ms"))] == "4.25");
    CHECK(a[size_t(column("commit"))] == "\"abc\"");
    // Last, the reference's flag: empty where the reference can tell techniques apart.
    CHECK(header.back() == "reference_flag");
    CHECK(a.back() == "\"\"");
}

TEST_CASE("results.md's table: the columns the list shows there, in its order") {
    const auto table = lines(markdown_table(run_of_two()));
    REQUIRE(table.size() == 4);
    std::vector<std::string> header;
    for (std::string cell : split(table[0], '|')) {
        const size_t first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
        if (first != std::string::npos) header.push_back(cell.substr(first, last - first + 1));
    }
    // No error metrics: the run has no reference.
    CHECK(header == std::vector<std::string>{"scene", "resolution", "technique", "parameters", "GPU ms", "± MAD", "CV %",
                                             "ratio", "wall ms", "passes (GPU ms)", "memory MiB", "status"});
    CHECK(table[3].find("cull 1.250, lit 1.250") != std::string::npos);
    CHECK(table[3].find("96x64") != std::string::npos);
}

TEST_CASE("dominated_by: pareto.md's judgement on the run's first Pareto axis, within a scene, from 6 rounds") {
    // shadow.pcf's first Pareto axis is visibility RMSE (tolerance 5e-4 absolute).
    const auto make = [](const std::string& id, double ratio, double visibility_rmse, int rounds,
                         const std::string& scene = "field") {
        CaseResult c = timed_case(id, {"lit"}, {});
        c.scene = scene;
        c.ok = true;
        c.technique = "shadow.pcf";
        c.params_shown = id;
        c.group = scene == "field" ? 0 : 1;
        c.group_baseline = id == "baseline";
        for (int r = 0; r < rounds; ++r) c.ratio.per_round.push_back(ratio * (1.0 + 0.01 * std::sin(2.4 * r)));
        c.ratio.estimate = median_with_ci(c.ratio.per_round, bootstrap_seed(id));
        ImageMetrics m{};
        m.visibility_rmse = visibility_rmse;
        m.columns.visibility = true;
        c.image_error = m;
        return c;
    };
    const auto run_of = [&](int rounds) {
        RunRecord run;
        run.frames_per_sample = 1;
        run.rounds = rounds;
        run.groups = {GroupRecord{"field 64x64", {}}, GroupRecord{"other 64x64", {}}};
        run.cases = {make("baseline", 1.0, 0.10, rounds),
                     make("fast", 0.5, 0.05, rounds),                 // beats the baseline in both
                     make("as_fast_worse", 0.5, 0.20, rounds),        // as fast as "fast", more error: beaten by it
                     make("slow_but_exact", 2.0, 0.01, rounds),       // the least error: on the front
                     make("elsewhere", 3.0, 0.50, rounds, "other")};  // another scene: nothing to compare with
        return run;
    };
    const ResultColumn* column = nullptr;
    for (const ResultColumn& c : result_columns())
        if (c.name == "dominated_by") column = &c;
    REQUIRE(column);
    const RunRecord run = run_of(30);
    const auto csv = column->csv(run);
    REQUIRE(csv.headers == std::vector<std::string>{"dominated_by"});
    const auto cell = [&](const RunRecord& r, size_t i) { return column->csv(r).cells(r.cases[i])[0]; };
    CHECK(cell(run, 0) == "\"fast\"");
    CHECK(cell(run, 1).empty());
    CHECK(cell(run, 2) == "\"fast\"");
    CHECK(cell(run, 3).empty());
    CHECK(cell(run, 4).empty());
    // The same judgement as pareto.md's front on that axis.
    for (const ParetoFront& front : pareto_fronts(run, "visibility_rmse"))
        for (const ParetoPoint& p : front.points) {
            CAPTURE(p.result->id);
            const size_t i = size_t(std::find_if(run.cases.begin(), run.cases.end(),
                                                 [&](const CaseResult& c) { return c.id == p.result->id; }) -
                                    run.cases.begin());
            CHECK(cell(run, i) == (p.dominated ? "\"" + p.dominated_by + "\"" : ""));
        }
    const auto markdown = column->markdown(run);
    REQUIRE(markdown.headers.size() == 1);
    CHECK(markdown.cells(run.cases[0])[0] == "shadow.pcf fast");
    CHECK(markdown.cells(run.cases[1])[0] == "-");
    // --quick's 3 rounds: no interval to judge by, nothing dominated (as canopy compare judges no change).
    const RunRecord quick = run_of(3);
    for (size_t i = 0; i < quick.cases.size(); ++i) CHECK(cell(quick, i).empty());
    // A failed case neither dominates nor is dominated.
    RunRecord failed = run;
    failed.cases[1].ok = false;
    CHECK(cell(failed, 0).empty());
    CHECK(cell(failed, 2).empty());
}

TEST_CASE("counters: a CSV column per name the run holds, and one results.md column when any case counted") {
    RunRecord run = run_of_two();
    run.cases[1].counters = {{"near_cells", 104}, {"far_macro_cells", 2.5}, {"field_cells", 202160}};
    const auto rows = lines(csv_report(run));
    REQUIRE(rows.size() == 3);
    const std::vector<std::string> header = split(rows[0], ','), a = split(rows[1], ','), b = split(rows[2], ',');
    const auto column = [&](const std::string& name) {
        for (size_t i = 0; i < header.size(); ++i)
            if (header[i] == name) return i;
        FAIL("no column " << name);
        return size_t(0);
    };
    CHECK(b[column("counter_near_cells")] == "104");
    CHECK(b[column("counter_far_macro_cells")] == "2.5");
    CHECK(a[column("counter_near_cells")].empty());  // case a counted nothing
    const auto table = lines(markdown_table(run));
    CHECK(table[0].find("counts") != std::string::npos);
    CHECK(table[3].find("near_cells 104, far_macro_cells 2.5, field_cells 202k") != std::string::npos);
    const auto cell = [](const std::string& row, size_t column) {
        std::vector<std::string> cells = split(row, '|');
        std::string c = cells.at(column);
        return c.substr(c.find_first_not_of(' '), c.find_last_not_of(' ') - c.find_first_not_of(' ') + 1);
    };
    const std::vector<std::string> headers = split(table[0], '|');
    size_t counts = 0;
    while (counts < headers.size() && headers[counts].find("counts") == std::string::npos) ++counts;
    CHECK(cell(table[2], counts) == "-");
    // Without counts, no column.
    CHECK(lines(markdown_table(run_of_two()))[0].find("counts") == std::string::npos);
}
