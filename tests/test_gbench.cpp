// results.gbench.json (report/gbench_report.hpp) has the structure Google Benchmark's JSON
// reporter writes (src/json_reporter.cc): a context with the machine, then per benchmark one
// "iteration" entry per repetition and the mean/median/stddev/cv aggregates.
#include "report/gbench_report.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace canopy;

namespace {

RunRecord two_cases() {
    RunRecord run;
    run.experiment = "tiny";
    run.config_file = "tests/data/experiments/tiny.toml";
    run.started_at = "2026-01-02T03:04:05Z";
    run.rounds = 4;
    run.frames_per_sample = 2;
    run.environment.hostname = "host";
    run.environment.nproc = 2;
    run.environment.cpu_mhz = 2299.6;
    run.environment.caches = {{"Data", 1, 49152, 1}, {"Unified", 3, 272629760, 2}};
    run.environment.load_average = {0.5, 0.25, 0.125};
    CaseResult a;
    a.id = "tiny_96x64_shadow.hard";
    a.group_baseline = true;
    a.gpu_frame = {"gpu_frame", {1.0, 2.0, 3.0, 4.0}, summarize({1.0, 2.0, 3.0, 4.0})};
    a.wall = {"wall", {1.5, 2.5, 3.5, 4.5}, summarize({1.5, 2.5, 3.5, 4.5})};
    a.cpu = {"cpu", {1.1, 2.1, 3.1, 4.1}, summarize({1.1, 2.1, 3.1, 4.1})};
    a.passes = {{"shadow_map", {0.1, 0.2, 0.3, 0.4}, {}}, {"lit", {0.9, 1.8, 2.7, 3.6}, {}}};
    a.counters = {{"near_cells", 220}};
    a.ratio.per_round = {1, 1, 1, 1};
    CaseResult failed;
    failed.id = "tiny_96x64_shadow.pcf";
    failed.ok = false;
    failed.error = "12 pixels are NaN or Inf";
    run.cases = {a, failed};
    return run;
}

}  // namespace

TEST_CASE("results.gbench.json: the context and the fields Google Benchmark writes") {
    const nlohmann::json j = nlohmann::json::parse(gbench_report(two_cases()));
    const auto& context = j.at("context");
    CHECK(context.at("date") == "2026-01-02T03:04:05+00:00");
    CHECK(context.at("host_name") == "host");
    CHECK(context.at("num_cpus") == 2);
    CHECK(context.at("mhz_per_cpu") == 2300);
    CHECK(context.at("caches").size() == 2);
    CHECK(context.at("caches")[1].at("size") == 272629760);
    CHECK(context.at("caches")[1].at("num_sharing") == 2);
    CHECK(context.at("load_avg").size() == 3);
    CHECK((context.at("library_build_type") == "release" || context.at("library_build_type") == "debug"));

    const auto& benchmarks = j.at("benchmarks");
    REQUIRE(benchmarks.size() == 4 + 4 + 1);  // 4 repetitions, 4 aggregates, the failed case
    for (const auto& b : benchmarks)
        for (const char* key : {"name", "family_index", "per_family_instance_index", "run_name", "run_type", "repetitions",
                                "threads", "iterations", "real_time", "cpu_time", "time_unit"}) {
            CAPTURE(key);
            CHECK(b.contains(key));
        }
    const auto& first = benchmarks[0];
    CHECK(first.at("name") == "tiny_96x64_shadow.hard/manual_time");
    CHECK(first.at("run_type") == "iteration");
    CHECK(first.at("repetitions") == 4);
    CHECK(first.at("repetition_index") == 0);
    CHECK(first.at("iterations") == 2);  // frames per sample
    CHECK(first.at("real_time") == 1.0);
    CHECK(first.at("cpu_time") == 1.1);
    CHECK(first.at("time_unit") == "ms");
    CHECK(first.at("wall_ms") == 1.5);
    CHECK(first.at("shadow_map_ms") == 0.1);
    CHECK(first.at("counter_near_cells") == 220);  // a technique's count, named apart from the passes
    CHECK(first.at("ratio") == 1.0);
    CHECK(benchmarks[3].at("repetition_index") == 3);

    // The aggregates, named and computed as Google Benchmark does.
    CHECK(benchmarks[4].at("name") == "tiny_96x64_shadow.hard/manual_time_mean");
    CHECK(benchmarks[4].at("run_name") == "tiny_96x64_shadow.hard/manual_time");
    CHECK(benchmarks[4].at("run_type") == "aggregate");
    CHECK(!benchmarks[4].contains("repetition_index"));
    CHECK(benchmarks[4].at("aggregate_name") == "mean");
    CHECK(benchmarks[4].at("aggregate_unit") == "time");
    CHECK(benchmarks[4].at("iterations") == 4);
    CHECK(benchmarks[4].at("real_time") == doctest::Approx(2.5));
    CHECK(benchmarks[5].at("aggregate_name") == "median");
    CHECK(benchmarks[5].at("real_time") == doctest::Approx(2.5));
    CHECK(benchmarks[6].at("aggregate_name") == "stddev");
    CHECK(benchmarks[6].at("real_time") == doctest::Approx(std::sqrt(5.0 / 3.0)));
    CHECK(benchmarks[7].at("aggregate_name") == "cv");
    CHECK(benchmarks[7].at("aggregate_unit") == "percentage");
    CHECK(benchmarks[7].at("real_time") == doctest::Approx(std::sqrt(5.0 / 3.0) / 2.5));

    const auto& failed = benchmarks[8];
    CHECK(failed.at("error_occurred") == true);
    CHECK(failed.at("error_message") == "12 pixels are NaN or Inf");
    CHECK(failed.at("family_index") == 1);
}

TEST_CASE("one repetition has no aggregates, as in Google Benchmark") {
    RunRecord run = two_cases();
    run.cases.resize(1);
    CaseResult& c = run.cases[0];
    for (TimingSeries* t : {&c.gpu_frame, &c.wall, &c.cpu}) t->samples_ms.resize(1);
    for (TimingSeries& p : c.passes) p.samples_ms.resize(1);
    c.ratio.per_round.resize(1);
    const nlohmann::json j = nlohmann::json::parse(gbench_report(run));
    REQUIRE(j.at("benchmarks").size() == 1);
    CHECK(j.at("benchmarks")[0].at("run_type") == "iteration");
}
