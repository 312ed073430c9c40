// Scenes the raster path used to crash on, and experiments whose cases cannot run: an empty
// scene renders its background, and every refused case is listed with a hint that fits why.
#include "config/experiment_config.hpp"
#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "run/experiment_runner.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/test_gpu.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

#include <optional>

using namespace canopy;
using test::contains;
using test::occurrences;

namespace {

std::optional<ConfigError> prepare_error(const Experiment& experiment) {
    return test::config_error_of([&] { prepare_experiment(experiment, TechniqueRegistry::instance(), test::gpu()); });
}

}  // namespace

TEST_CASE("a scene with no objects renders its background with every kind of shadow map") {
    // Before: a segfault on the zero-size vertex buffer.
    const Scene scene = parse_scene("[scene]\nbackground = [0.25, 0.5, 1]\n[[light]]\ntype = \"sphere\"\n", "empty.toml");
    for (const char* technique : {"shadow.hard", "shadow.pcss", "shadow.vsm", "shadow.ssss"}) {
        CAPTURE(technique);
        const Image image = test::render_technique(scene, technique, {}, 32, 24);
        REQUIRE(image.width == 32);
        bool background = true;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const float* p = &image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
                background = background && p[0] == 0.25f && p[1] == 0.5f && p[2] == 1.0f;
            }
        CHECK(background);
    }
}

TEST_CASE("every refused case is listed, one line each, with a hint that fits the cause") {
    test::TempFolder folder;
    folder.write("point.toml", "[scene]\nname = \"point\"\n[[light]]\ntype = \"spot\"\n[[object]]\nshape = \"box\"\n");
    folder.write("dark.toml",
                 "[scene]\nname = \"dark\"\n[[light]]\ntype = \"sphere\"\ncasts_shadows = false\n[[object]]\nshape = \"box\"\n");
    folder.write("area.toml", "[scene]\nname = \"area\"\n[[light]]\ntype = \"sphere\"\n[[object]]\nshape = \"box\"\n");
    const std::filesystem::path file = folder.write(
        "e.toml", "[experiment]\nscenes = [\"area.toml\", \"point.toml\", \"dark.toml\"]\nresolutions = [[16, 16], [32, 32]]\n"
                  "[[technique]]\nname = \"shadow.hard\"\n"
                  "[[technique]]\nname = \"shadow.pcss\"\n[technique.params]\nkernel = [3, 5]\n");
    const Experiment experiment = load_experiment(file, TechniqueRegistry::instance());
    const auto error = prepare_error(experiment);
    REQUIRE(error);
    const std::string message = error->what(), hint = error->hint();
    INFO(error->formatted());
    // point: 2 resolutions x 2 PCSS kernels need an area light; dark: all 6 cases lack a shadow light.
    CHECK(contains(message, "10 of 18 cases cannot run"));
    CHECK(occurrences(message, "\n    ") == 10);
    CHECK(occurrences(message, "needs an area light") == 4);
    CHECK(occurrences(message, "no shadow-casting light") == 6);
    CHECK(contains(message, "point_32x32_shadow.pcss_kernel-5"));
    CHECK(!contains(message, "area_"));
    // One hint per cause, each pointing at the light to change, none at the device.
    CHECK(contains(hint, "give the shadow light a size"));
    CHECK(contains(hint, "point.toml:3"));
    CHECK(contains(hint, "casts_shadows = true"));
    CHECK(contains(hint, "dark.toml:3"));
    CHECK(!contains(hint, "--device"));
    CHECK(error->line() == 6);  // the first refused case's [[technique]] (PCSS on point.toml)
}

TEST_CASE("a long list of refused cases is capped") {
    test::TempFolder folder;
    folder.write("point.toml", "[scene]\nname = \"point\"\n[[light]]\ntype = \"directional\"\n[[object]]\nshape = \"box\"\n");
    const std::filesystem::path file = folder.write(
        "e.toml", "[experiment]\nscenes = [\"point.toml\"]\n"
                  "[[technique]]\nname = \"shadow.pcss\"\n[technique.params]\nkernel = [1, 3, 5, 7, 9, 11, 13, 15]\n"
                  "blocker_search = [1, 2, 3]\n");
    const Experiment experiment = load_experiment(file, TechniqueRegistry::instance());
    const auto error = prepare_error(experiment);
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(contains(error->what(), "24 of 24 cases cannot run"));
    CHECK(occurrences(error->what(), "needs an area light") == 20);
    CHECK(contains(error->what(), "... and 4 more"));
}

TEST_CASE("check_supported: a missing area light and a missing shadow light have scene hints") {
    const Technique& pcss = *TechniqueRegistry::instance().find("shadow.pcss");
    const FrameGraph plan = pcss.graph(ParamSet::resolve(pcss.params(), {}, {}, {}, "shadow.pcss"));
    Scene scene = parse_scene("[[light]]\ntype = \"directional\"\n", "s.toml");
    auto unsupported = check_supported(test::gpu(), scene, plan);
    REQUIRE(unsupported);
    CHECK(contains(unsupported->hint, "rect"));
    CHECK(contains(unsupported->hint, "s.toml:1"));
    CHECK(unsupported_reason(test::gpu(), scene, plan) == unsupported->reason);
    scene.lights[0].type = LightType::sphere;
    CHECK(!check_supported(test::gpu(), scene, plan));
}

TEST_CASE("a technique made for a population kind is refused on a scene without one, by run and by plan") {
    // grass.geometry on a scene of boxes would time and score the boxes alone.
    test::TempFolder folder;
    folder.write("boxes.toml", "[scene]\nname = \"boxes\"\n[[light]]\ntype = \"directional\"\n[[object]]\nshape = \"box\"\n");
    const std::filesystem::path file = folder.write(
        "e.toml", "[experiment]\nscenes = [\"boxes.toml\"]\nresolutions = [[16, 16]]\n"
                  "[[technique]]\nname = \"shadow.hard\"\n[[technique]]\nname = \"grass.geometry\"\n");
    const Experiment experiment = load_experiment(file, TechniqueRegistry::instance());
    const auto check = [&](const std::optional<ConfigError>& error) {
        REQUIRE(error);
        INFO(error->formatted());
        CHECK(contains(error->what(), "1 case cannot run"));
        CHECK(contains(error->what(), "boxes_16x16_grass.geometry: scene 'boxes' holds no 'grass' population"));
        CHECK(contains(error->hint(), "add a [[population]] of kind 'grass'"));
        CHECK(contains(error->hint(), "boxes.toml"));
        CHECK(error->line() == 6);  // grass.geometry's [[technique]]
    };
    check(prepare_error(experiment));
    const std::vector<Case> cases = expand_cases(experiment, TechniqueRegistry::instance());
    check(test::config_error_of([&] { refuse_cases_scenes_cannot_run(experiment, cases, TechniqueRegistry::instance()); }));
    // plan refuses what no device decides, as run does: a light missing here.
    test::TempFolder dark;
    dark.write("dark.toml",
               "[scene]\nname = \"dark\"\n[[light]]\ntype = \"sphere\"\ncasts_shadows = false\n[[object]]\nshape = \"box\"\n");
    const Experiment unlit = load_experiment(
        dark.write("e.toml", "[experiment]\nscenes = [\"dark.toml\"]\n[[technique]]\nname = \"shadow.hard\"\n"),
        TechniqueRegistry::instance());
    const auto error = test::config_error_of(
        [&] { refuse_cases_scenes_cannot_run(unlit, expand_cases(unlit, TechniqueRegistry::instance()), TechniqueRegistry::instance()); });
    REQUIRE(error);
    CHECK(contains(error->what(), "no shadow-casting light"));
}
