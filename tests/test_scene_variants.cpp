// A scene variant in an experiment's `scenes` may give the scene another camera (`camera = {...}`,
// the keys of [camera]): the keys given replace the scene's, the others are kept, and a wrong key
// or value names its line and the fix, as in a scene file.
#include "config/experiment_config.hpp"
#include "core/registry.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

using namespace canopy;

TEST_CASE("a scene variant's camera replaces the keys it gives and keeps the others") {
    test::TempFolder folder;
    folder.write("scene.toml", "[camera]\nposition = [0, 2, 6]\nfov = 50\nnear = 0.2\n[[light]]\ntype = \"directional\"\n");
    const std::filesystem::path file = folder.write(
        "experiment.toml",
        "[experiment]\nscenes = [\"scene.toml\", { file = \"scene.toml\", name = \"far\", camera = { position = [0, 30, 60], fov = 5 } }]\n"
        "[[technique]]\nname = \"shadow.hard\"\n");
    const Experiment e = load_experiment(file, TechniqueRegistry::instance());
    REQUIRE(e.scenes.size() == 2);
    CHECK(e.scenes[0].camera.position == glm::vec3(0, 2, 6));
    CHECK(e.scenes[0].camera.fov_y_degrees == doctest::Approx(50));
    CHECK(e.scenes[1].name == "far");
    CHECK(e.scenes[1].camera.position == glm::vec3(0, 30, 60));
    CHECK(e.scenes[1].camera.fov_y_degrees == doctest::Approx(5));
    CHECK(e.scenes[1].camera.near_plane == doctest::Approx(0.2));  // kept
    CHECK(e.scenes[1].camera.target == e.scenes[0].camera.target);
}

TEST_CASE("a scene variant's camera mistakes name their line and the fix") {
    test::TempFolder folder;
    folder.write("scene.toml", "[[light]]\ntype = \"directional\"\n");
    const auto error_of = [&](const std::string& camera) {
        const std::filesystem::path file = folder.write(
            "experiment.toml", "[experiment]\nscenes = [\n  \"scene.toml\",\n  { file = \"scene.toml\", name = \"v\", camera = " +
                                   camera + " },\n]\n[[technique]]\nname = \"shadow.hard\"\n");
        return test::config_error_of([&] { load_experiment(file, TechniqueRegistry::instance()); });
    };
    for (const auto& [camera, words] : std::vector<std::pair<std::string, std::string>>{
             {"{ fov = 200 }", "(0, 179)"},
             {"{ position = [0, 0, 0], target = [0, 0, 0] }", "equals its 'position'"},
             {"{ zoom = 2 }", "zoom"},
             {"{ near = 5, far = 1 }", "greater than 'near'"}}) {
        CAPTURE(camera);
        const auto error = error_of(camera);
        REQUIRE(error.has_value());
        CAPTURE(error->formatted());
        CHECK(error->line() == 4);
        CHECK(test::contains(error->formatted(), words));
    }
}
