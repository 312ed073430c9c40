// A group measured round by round (run/group_measurement.hpp): the order of samples, the pairing
// with the baseline, chunks with the baseline in each, and images identical to a renderer's own.
#include "config/experiment_config.hpp"
#include "render/frame_renderer.hpp"
#include "run/experiment_runner.hpp"
#include "run/group_measurement.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <cstring>

using namespace canopy;

namespace {

struct TinyGroup {
    Experiment experiment;
    PreparedExperiment prepared;
    GroupInput input;

    TinyGroup() {
        const TechniqueRegistry& registry = TechniqueRegistry::instance();
        experiment = load_experiment(std::string(CANOPY_TEST_DATA) + "/experiments/tiny.toml", registry);
        prepared = prepare_experiment(experiment, registry, test::gpu());
        input.name = "tiny 96x64";
        input.scene = &experiment.scenes[0];
        input.meshes = &prepared.meshes[0];
        for (const Case& c : prepared.cases) input.cases.push_back({&c, registry.find(c.technique), 0});
    }
};

MeasurementSettings settings(BaselinePairing pairing, int rounds = 4) {
    MeasurementSettings s;
    s.warmup_frames = 1;
    s.rounds = rounds;
    s.frames_per_sample = 2;
    s.pairing = pairing;
    return s;
}

}  // namespace

TEST_CASE("adjacent pairing: every case between two baseline samples, in a new order each round") {
    TinyGroup g;
    REQUIRE(g.input.cases.size() == 3);
    std::vector<size_t> measured;
    GroupCallbacks callbacks;
    callbacks.case_measured = [&](size_t index, CaseResult&, Image&& image, Image&&) {
        measured.push_back(index);
        CHECK(image.width == 96);
    };
    const auto group = measure_group(test::gpu(), g.input, settings(BaselinePairing::adjacent), {}, callbacks);
    REQUIRE(group.has_value());
    CHECK(measured == std::vector<size_t>{0, 1, 2});
    REQUIRE(group->record.chunks.size() == 1);
    const MeasurementChunk& chunk = group->record.chunks[0];
    CHECK(chunk.cases == group->record.cases);
    REQUIRE(chunk.orders.size() == 4);
    CHECK(chunk.orders[0] == std::vector<size_t>{0, 1, 0, 2, 0});
    CHECK(chunk.orders[1] == std::vector<size_t>{0, 2, 0, 1, 0});
    CHECK(chunk.baseline_gpu_ms.size() == 4);
    for (const CaseResult& c : group->cases) {
        CAPTURE(c.id);
        CHECK(c.ok);
        CHECK(c.gpu_frame.samples_ms.size() == 4);
        CHECK(c.sample_start_s.size() == 4);
        CHECK(c.cpu.samples_ms.size() == 4);
        REQUIRE(c.ratio.per_round.size() == 4);
        CHECK(c.ratio.estimate.ci.low <= c.ratio.estimate.value);
        CHECK(c.ratio.estimate.value <= c.ratio.estimate.ci.high);
    }
    CHECK(group->cases[0].group_baseline);
    CHECK(group->cases[0].ratio.per_round == std::vector<double>(4, 1.0));
    // The baseline's round sample is the mean of its 3 samples in the round.
    CHECK(group->cases[0].gpu_frame.samples_ms == chunk.baseline_gpu_ms);
    // A sample's ratio lies between its time over the slower and over the faster baseline.
    CHECK(group->cases[1].ratio.per_round[0] > 0.0);
}

TEST_CASE("round pairing: a Williams order of all cases, each divided by the round's baseline sample") {
    TinyGroup g;
    const auto group = measure_group(test::gpu(), g.input, settings(BaselinePairing::round, 6), {}, {});
    REQUIRE(group.has_value());
    const MeasurementChunk& chunk = group->record.chunks[0];
    REQUIRE(chunk.orders.size() == 6);
    CHECK(chunk.orders[0] == std::vector<size_t>{0, 1, 2});
    CHECK(chunk.orders[1] == std::vector<size_t>{1, 2, 0});
    CHECK(chunk.orders[3] == std::vector<size_t>{2, 1, 0});  // odd n: the reversed rows follow
    const CaseResult& pcf = group->cases[1];
    for (size_t r = 0; r < 6; ++r)
        CHECK(pcf.ratio.per_round[r] == pcf.gpu_frame.samples_ms[r] / chunk.baseline_gpu_ms[r]);
}

TEST_CASE("a group larger than a chunk is measured in chunks, the baseline in each") {
    TinyGroup g;
    ChunkLimits limits;
    limits.max_cases = 2;
    std::vector<size_t> measured;
    GroupCallbacks callbacks;
    callbacks.case_measured = [&](size_t index, CaseResult&, Image&&, Image&&) { measured.push_back(index); };
    const auto group = measure_group(test::gpu(), g.input, settings(BaselinePairing::adjacent), limits, callbacks);
    REQUIRE(group.has_value());
    REQUIRE(group->record.chunks.size() == 2);
    CHECK(measured == std::vector<size_t>{0, 1, 2});  // the baseline's record is its first chunk's
    CHECK(group->record.chunks[0].cases == std::vector<std::string>{g.prepared.cases[0].id, g.prepared.cases[1].id});
    CHECK(group->record.chunks[1].cases == std::vector<std::string>{g.prepared.cases[0].id, g.prepared.cases[2].id});
    CHECK(group->record.chunks[1].baseline_gpu_ms.size() == 4);  // the baseline's own samples of that chunk
    CHECK(group->cases[2].chunk == 1);
    CHECK(group->cases[2].ratio.per_round.size() == 4);
    CHECK(group->cases[0].gpu_frame.samples_ms.size() == 4);
}

TEST_CASE("a case's image is the one its renderer alone renders, bit for bit") {
    TinyGroup g;
    std::vector<Image> images(3);
    GroupCallbacks callbacks;
    callbacks.case_measured = [&](size_t index, CaseResult&, Image&& image, Image&&) { images[index] = std::move(image); };
    REQUIRE(measure_group(test::gpu(), g.input, settings(BaselinePairing::adjacent), {}, callbacks).has_value());
    for (size_t i = 0; i < 3; ++i) {
        const Case& c = g.prepared.cases[i];
        FrameRenderer alone(test::gpu(), g.experiment.scenes[0], g.prepared.meshes[0], 96, 64,
                            g.input.cases[i].technique->graph(c.params));
        alone.render();
        const Image expected = alone.read_color();
        REQUIRE(images[i].pixels.size() == expected.pixels.size());
        CHECK(std::memcmp(images[i].pixels.data(), expected.pixels.data(), expected.pixels.size() * sizeof(float)) == 0);
    }
}
