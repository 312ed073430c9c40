// `canopy bench grass-transitions` (benchmarks/grass_transitions.cpp) on a small field: a step back
// sends every blade that switches to the next band; sharp bands gather the switching blades in a
// narrow depth, Boulanger's smooth ones spread them; and with no step nothing switches. Checked
// with numbers the benchmark writes, against the field as this test builds it.
#include "config/scene_config.hpp"
#include "run/family_benchmark.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

using namespace canopy;

namespace {

const FamilyBenchmark& transitions() {
    for (const FamilyBenchmark* b : FamilyBenchmarkRegistry::instance().all())
        if (b->name() == "grass-transitions") return *b;
    FAIL("no grass-transitions benchmark");
    throw 0;
}

// 24 x 24 cells of 200 blades, the eye looking along the field from its edge: cells 0 to 30 m away.
Scene field() {
    return parse_scene(R"([scene]
name = "transitions"
[camera]
position = [0, 1.7, 14]
target = [0, 0, 0]
[[light]]
type = "directional"
direction = [-0.3, -1, -0.2]
[[population]]
name = "grass"
kind = "grass"
params = { cells_x = 24, cells_z = 24, blades = 200 }
)",
                       "transitions.toml");
}

// `filtered_eyes`: the filtered-texel table's eyes (0: none; the table is the costly part under
// the sanitizers).
nlohmann::json numbers(double step, const std::string& transition, long long filtered_eyes = 0) {
    const FamilyBenchmark& b = transitions();
    const ParamSet params = ParamSet::resolve(b.params(),
                                              {{"step", step},
                                               {"eye_distance", 12.0},
                                               {"transition", transition},
                                               {"filtered_eyes", filtered_eyes}},
                                              {}, {}, "grass-transitions");
    return b.run(test::gpu(), field(), params).numbers;
}

nlohmann::json run(double step, const std::string& transition = "binary") {
    return numbers(step, transition).at("configurations");
}

}  // namespace

TEST_CASE("grass transitions: a step back moves switching blades to the next band, sharp bands gather them") {
    const nlohmann::json rows = run(0.5);
    REQUIRE(rows.size() == 6);  // three band settings x two transitions
    for (const nlohmann::json& r : rows) {
        CAPTURE(r.dump());
        CHECK(r.at("blades_drawn").get<uint64_t>() == 24u * 24u * 200u);
        CHECK(r.at("other_switches").get<uint64_t>() == 0);
    }
    // Rows 2-3: smooth (4-10 m, 14-20 m); rows 4-5: sharp (9.5-10 m, 19.5-20 m).
    for (int k = 0; k < 2; ++k) {
        const nlohmann::json &smooth = rows[size_t(2 + k)], &sharp = rows[size_t(4 + k)];
        CAPTURE(k);
        CHECK(smooth.at("switching").get<uint64_t>() > 20);
        CHECK(sharp.at("switching").get<uint64_t>() > 20);
        const double smooth_spread = smooth.at("depth_p95").get<double>() - smooth.at("depth_p5").get<double>();
        const double sharp_spread = sharp.at("depth_p95").get<double>() - sharp.at("depth_p5").get<double>();
        CAPTURE(smooth_spread);
        CAPTURE(sharp_spread);
        CHECK(smooth_spread > 2.0 * sharp_spread);
        // Sharp: the switching blades lie at the band's edge (10 or 20 m), within a cell and the step.
        const double edge = k == 0 ? 10.0 : 20.0;
        CHECK(sharp.at("depth_p5").get<double>() > edge - 2.0);
        CHECK(sharp.at("depth_p95").get<double>() < edge + 2.0);
        CHECK(smooth.at("cells_switching").get<uint64_t>() > sharp.at("cells_switching").get<uint64_t>());
    }
}

TEST_CASE("grass transitions: two eyes at the same place switch nothing") {
    for (const std::string transition : {"binary", "lemme"})
        for (const nlohmann::json& r : run(0.001, transition)) {
            CAPTURE(transition);
            CHECK(r.at("share_moved").get<double>() < double(r.at("blades_drawn").get<uint64_t>()) / 1000.0);
        }
}

TEST_CASE("grass transitions: a window moves the blades' worth a binary cut moves, spread over more blades") {
    // A step moves each cut by the same share of the thresholds whatever the window (away from the
    // band's ends): the shares moved match the binary cut's switching blades, and more blades move.
    const nlohmann::json binary = run(0.5, "binary");
    for (const std::string transition : {"lemme", "boulanger"}) {
        const nlohmann::json smooth = run(0.5, transition);
        for (size_t i = 2; i < 6; ++i) {
            CAPTURE(transition);
            CAPTURE(i);
            const double moved = smooth[i].at("share_moved").get<double>();
            const double switching = double(binary[i].at("switching").get<uint64_t>());
            CHECK(binary[i].at("share_moved").get<double>() == doctest::Approx(switching));
            CHECK(moved == doctest::Approx(switching).epsilon(0.1));
            // On the smooth bands (rows 2-3) the step moves the cut by a fraction of the window.
            if (i < 4) CHECK(double(smooth[i].at("switching").get<uint64_t>()) > 1.5 * switching);
        }
    }
}

TEST_CASE("grass transitions: filtered texels cutting at their blades' mean root draw at most 0.5 % of the blades "
          "twice or never at grass.lod's defaults, up to 32-texel footprints") {
    // 24 eyes every 5 m: the worst eye of the default 48 lies within a few percent of these.
    const nlohmann::json rows = numbers(0.25, "lemme", 24).at("filtered_roots");
    REQUIRE(rows.size() == 18);  // three band settings x six levels
    for (size_t i = 0; i < 6; ++i) {
        const nlohmann::json& r = rows[i];  // grass.lod's defaults
        CAPTURE(r.dump());
        const double near = r.at("near_middle_worst_share").get<double>();
        if (r.at("level").get<int>() <= 5) {
            CHECK(near <= 0.005);
            CHECK(r.at("middle_far_estimate_worst_share").get<double>() <= 0.005);
        }
        // Wider footprints hold roots farther from their mean.
        if (i > 0) CHECK(near >= rows[i - 1].at("near_middle_worst_share").get<double>());
    }
    CHECK(rows[5].at("near_middle_worst_share").get<double>() > 0.0);
}
