// The run plan (run/run_plan.hpp): case keys, cost estimates, shards of whole groups balanced by
// cost, and --shard's parsing.
#include "config/experiment_config.hpp"
#include "run/run_plan.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

using namespace canopy;

TEST_CASE("shards take whole groups, the most costly first, each to the least loaded shard") {
    // The most costly first to the least loaded: 9 -> 0, 7 -> 1, 5 -> 1, 4 -> 0, 3 -> 1 (13 and 15).
    const std::vector<double> cost{5, 9, 3, 7, 4};
    const std::vector<size_t> shard = assign_shards(cost, 2);
    REQUIRE(shard.size() == cost.size());
    std::vector<double> load(2, 0.0);
    for (size_t g = 0; g < cost.size(); ++g) load[shard[g]] += cost[g];
    CHECK(load[0] + load[1] == doctest::Approx(28));
    CHECK(std::abs(load[0] - load[1]) <= 2.0);  // 14 / 14 or 13 / 15, not by count (3 / 2 groups)
    CHECK(shard[1] == 0);                       // the dearest group goes to the first shard
    CHECK(shard[3] == 1);
    // Deterministic, and one shard takes everything.
    CHECK(assign_shards(cost, 2) == shard);
    CHECK(assign_shards(cost, 1) == std::vector<size_t>(5, 0));
    // More shards than groups: some are empty, none holds two groups.
    const std::vector<size_t> many = assign_shards({1, 2}, 4);
    CHECK(many[0] != many[1]);
    CHECK_THROWS_AS(assign_shards(cost, 0), std::invalid_argument);
}

TEST_CASE("--shard i/N is 1-based, whole numbers, i <= N; anything else says what to give") {
    CHECK(parse_shard("1/1").index == 0);
    CHECK(parse_shard("3/4").index == 2);
    CHECK(parse_shard("3/4").count == 4);
    CHECK(parse_shard("3/4").text() == "3/4");
    for (const char* bad : {"0/2", "3/2", "2", "a/b", "1/0", "-1/2", "1/2/3", "", "1.5/2"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(parse_shard(bad), std::invalid_argument);
    }
}

TEST_CASE("a case's key depends on the case alone; its cost on its frames and the pixels its passes cover") {
    const Experiment e = load_experiment(std::string(CANOPY_TEST_DATA) + "/experiments/tiny.toml", TechniqueRegistry::instance());
    const std::vector<Case> cases = expand_cases(e, TechniqueRegistry::instance());
    REQUIRE(cases.size() == 3);
    std::set<std::string> keys;
    for (const Case& c : cases) keys.insert(case_key(c, e.scenes[c.scene_index]));
    CHECK(keys.size() == 3);
    CHECK(case_key(cases[0], e.scenes[0]).size() == 16);
    Case moved = cases[1];
    moved.id = "another id, another place in another experiment";
    CHECK(case_key(moved, e.scenes[0]) == case_key(cases[1], e.scenes[0]));
    Case bigger = cases[1];
    bigger.resolution = {192, 128};
    CHECK(case_key(bigger, e.scenes[0]) != case_key(cases[1], e.scenes[0]));

    const Technique& pcf = *TechniqueRegistry::instance().find("shadow.pcf");
    MeasurementSettings settings;
    settings.warmup_frames = 0;
    settings.rounds = 10;
    const double base = estimated_case_cost(cases[1], pcf, settings, true);
    CHECK(base > 0);
    CHECK(estimated_case_cost(cases[1], pcf, settings, false) == doctest::Approx(2 * base));  // the baseline renders beside it
    settings.rounds = 20;
    CHECK(estimated_case_cost(cases[1], pcf, settings, true) == doctest::Approx(2 * base));
    settings.rounds = 10;
    CHECK(estimated_case_cost(bigger, pcf, settings, true) > base);  // 4x the screen

    const RunPlan plan = plan_run(e, cases, TechniqueRegistry::instance(), settings);
    REQUIRE(plan.groups.size() == 1);
    CHECK(plan.group_cost[0] == doctest::Approx(plan.case_cost[0] + plan.case_cost[1] + plan.case_cost[2]));
}
