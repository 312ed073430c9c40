// Camera paths (scene/camera_path.hpp, config [camera_path]): the interpolation, every config
// mistake at its line, and a measured group whose frames follow the path: one traversal per
// sample, per-frame times recorded, the image taken at the scene's camera afterwards.
#include "config/experiment_config.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "run/experiment_runner.hpp"
#include "run/group_measurement.hpp"
#include "scene/camera_path.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/test_gpu.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace canopy;
using test::config_error_of;

namespace {

CameraPath three_poses() {
    CameraPath path;
    path.frames = 5;
    path.poses = {{{0, 1, 4}, {0, 0, 0}, 0.0f}, {{4, 1, 0}, {0, 0, 0}, 60.0f}, {{0, 1, -4}, {1, 0, 0}, 0.0f}};
    return path;
}

bool near(const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-5f; }

}  // namespace

TEST_CASE("a camera path passes through its poses, evenly spread over the frames, linear between") {
    const CameraPath path = three_poses();
    Camera base;
    base.up = {0, 1, 0};
    base.fov_y_degrees = 40.0f;
    base.near_plane = 0.2f;
    // Poses at frames 0, 2, 4 (frames - 1 = 4 spread over 2 segments).
    CHECK(near(path.at(base, 0).position, {0, 1, 4}));
    CHECK(near(path.at(base, 2).position, {4, 1, 0}));
    CHECK(near(path.at(base, 4).position, {0, 1, -4}));
    CHECK(near(path.at(base, 4).target, {1, 0, 0}));
    CHECK(near(path.at(base, 1).position, {2, 1, 2}));
    CHECK(near(path.at(base, 3).target, {0.5f, 0, 0}));
    // fov 0 keeps the scene camera's; between two poses it is interpolated too.
    CHECK(path.at(base, 0).fov_y_degrees == doctest::Approx(40.0));
    CHECK(path.at(base, 2).fov_y_degrees == doctest::Approx(60.0));
    CHECK(path.at(base, 1).fov_y_degrees == doctest::Approx(50.0));
    // Up and clip planes come from the scene's camera; frames wrap around the traversal.
    CHECK(path.at(base, 3).near_plane == doctest::Approx(0.2));
    CHECK(near(path.at(base, 7).position, path.at(base, 2).position));
}

TEST_CASE("[camera_path] mistakes name their line and the fix") {
    test::TempFolder folder;
    folder.write("scene.toml", "[camera]\nposition = [0, 2, 6]\n[[light]]\ntype = \"directional\"\n");
    const std::string head = "[experiment]\nscenes = [\"scene.toml\"]\n\n[[technique]]\nname = \"shadow.hard\"\n\n";
    const std::string pose_a = "[[camera_path.pose]]\nposition = [0, 2, 6]\ntarget = [0, 0, 0]\n";
    const std::string pose_b = "[[camera_path.pose]]\nposition = [4, 2, 4]\ntarget = [0, 0, 0]\n";
    auto error_of = [&](const std::string& text) {
        const std::filesystem::path file = folder.write("experiment.toml", head + text);
        return config_error_of([&] { load_experiment(file, TechniqueRegistry::instance()); });
    };
    {
        const std::filesystem::path file = folder.write("experiment.toml", head + "[camera_path]\nframes = 8\n" + pose_a + pose_b);
        const Experiment e = load_experiment(file, TechniqueRegistry::instance());
        REQUIRE(e.camera_path.has_value());
        CHECK(e.camera_path->frames == 8);
        CHECK(e.camera_path->poses.size() == 2);
    }
    const auto at_line = [&](const std::string& text, int line, const std::string& words) {
        const auto error = error_of(text);
        REQUIRE(error.has_value());
        CAPTURE(error->formatted());
        CHECK(error->line() == line);
        CHECK(test::contains(error->formatted(), words));
    };
    at_line("[camera_path]\n" + pose_a + pose_b, 7, "needs 'frames'");
    at_line("[camera_path]\nframes = 1\n" + pose_a + pose_b, 8, "[2, 10000]");
    at_line("[camera_path]\nframes = 8\n" + pose_a, 7, "at least two");
    at_line("[camera_path]\nframes = 8\n" + pose_a + "[[camera_path.pose]]\nposition = [1, 2, 3]\n", 12, "both 'position' and 'target'");
    at_line("[camera_path]\nframes = 8\n" + pose_a + "[[camera_path.pose]]\nposition = [1, 2, 3]\ntarget = [1, 2, 3]\n", 14,
            "'target' equals 'position'");
    at_line("[camera_path]\nframes = 8\n" + pose_a + "[[camera_path.pose]]\nposition = [0, 5, 0]\ntarget = [0, 0, 0]\n", 14,
            "looks along the 'up'");
    at_line("[camera_path]\nframes = 8\n" + pose_a + "[[camera_path.pose]]\nposition = [2e6, 0, 0]\ntarget = [0, 0, 0]\n", 13,
            "coordinate range");
    at_line("[camera_path]\nframes = 8\n" + pose_a + pose_b + "fov = 200\n", 15, "(0, 179)");
    at_line("[camera_path]\nframes = 8\n" + pose_a + pose_b + "roll = 1\n", 15, "roll");
    at_line("[camera_path]\nframes = 3\nposes = 2\n", 9, "poses");
    {
        // A sample is one traversal: frames_per_sample means nothing beside a path.
        const std::filesystem::path file = folder.write(
            "experiment.toml", "[experiment]\nscenes = [\"scene.toml\"]\nframes_per_sample = 2\n\n[[technique]]\nname = "
                               "\"shadow.hard\"\n\n[camera_path]\nframes = 8\n" + pose_a + pose_b);
        const auto error = config_error_of([&] { load_experiment(file, TechniqueRegistry::instance()); });
        REQUIRE(error.has_value());
        CHECK(error->line() == 3);
        CHECK(test::contains(error->formatted(), "one traversal"));
    }
}

TEST_CASE("a measured group follows the path: per-frame times, the image at the scene's camera") {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    Experiment experiment = load_experiment(std::string(CANOPY_TEST_DATA) + "/experiments/tiny.toml", registry);
    PreparedExperiment prepared = prepare_experiment(experiment, registry, test::gpu());
    const Scene& scene = experiment.scenes[0];
    GroupInput input;
    input.name = "tiny 96x64";
    input.scene = &scene;
    input.meshes = &prepared.meshes[0];
    for (const Case& c : prepared.cases) input.cases.push_back({&c, registry.find(c.technique), 0});
    input.cases.resize(2);

    MeasurementSettings settings;
    settings.warmup_frames = 1;
    settings.rounds = 3;
    CameraPath path;
    path.frames = 4;
    // From the scene's camera to one looking at the scene from far away: the frames differ.
    const glm::vec3 far = scene.camera.target + 6.0f * (scene.camera.position - scene.camera.target);
    path.poses = {{scene.camera.position, scene.camera.target, 0.0f}, {far, scene.camera.target, 0.0f}};
    settings.camera_path = path;
    settings.frames_per_sample = path.frames;

    std::vector<Image> images;
    std::vector<FrameState> baseline_frames;
    GroupCallbacks callbacks;
    callbacks.case_measured = [&](size_t, CaseResult&, Image&& image, Image&&) { images.push_back(std::move(image)); };
    callbacks.frame_rendered = [&](size_t index, const FrameState& state) {
        if (index == 0) baseline_frames.push_back(state);
    };
    const auto group = measure_group(test::gpu(), input, settings, {}, callbacks);
    REQUIRE(group.has_value());
    for (const CaseResult& c : group->cases) {
        CAPTURE(c.id);
        REQUIRE(c.ok);
        REQUIRE(c.path_frames.size() == 4);
        for (const CaseResult::PathFrame& f : c.path_frames) {
            CHECK(f.gpu_frame.samples_ms.size() == 3);
            CHECK(f.passes.size() == c.passes.size());
        }
        // A sample's time is the mean over its traversal's frames.
        for (size_t r = 0; r < 3; ++r) {
            double sum = 0;
            for (const CaseResult::PathFrame& f : c.path_frames) sum += f.gpu_frame.samples_ms[r];
            CHECK(c.gpu_frame.samples_ms[r] == doctest::Approx(sum / 4).epsilon(1e-9));
        }
    }
    // Every frame follows the path, frame indices counting on: 1 warm-up frame (the path's first),
    // then per round, under adjacent pairing, the baseline's traversal before and after the other
    // case's (2 traversals of 4), then one more frame at the scene's camera for the image.
    REQUIRE(baseline_frames.size() == 1 + 3 * 2 * 4 + 1);
    for (size_t f = 0; f < baseline_frames.size(); ++f) {
        CAPTURE(f);
        CHECK(baseline_frames[f].frame_index == f);
        const Camera expected = f == 0 ? path.at(scene.camera, 0)
                                : f + 1 == baseline_frames.size() ? scene.camera
                                                                  : path.at(scene.camera, int((f - 1) % 4));
        CHECK(glm::length(baseline_frames[f].camera.position - expected.position) < 1e-5f);
        CHECK(glm::length(baseline_frames[f].camera.target - expected.target) < 1e-5f);
    }
    // The image errors are measured on is the scene camera's, not the path's last frame.
    REQUIRE(images.size() == 2);
    FrameRenderer alone(test::gpu(), scene, prepared.meshes[0], 96, 64, registry.find(prepared.cases[0].technique)->graph(prepared.cases[0].params));
    alone.render();
    const Image expected = alone.read_color();
    CHECK(images[0].pixels == expected.pixels);
    alone.render(FrameState{1, path.at(scene.camera, 3)});
    CHECK(alone.read_color().pixels != expected.pixels);  // the path's last frame looks elsewhere
}
