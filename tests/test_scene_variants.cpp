// A scene variant in an experiment's `scenes` may give the scene another camera (`camera = {...}`,
// the keys of [camera]): the keys given replace the scene's, the others are kept, and a wrong key
// or value names its line and the fix, as in a scene file.
#include "config/experiment_config.hpp"
#include "core/registry.hpp"
#include "scene/population_kind.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

#include <cmath>

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
    // Each case records the overrides it ran with (results.json's scene_variant), on one line.
    CHECK(e.scenes[0].variant.empty());
    CHECK(e.scenes[1].variant.find("name = 'far'") != std::string::npos);
    CHECK(e.scenes[1].variant.find("fov = 5") != std::string::npos);
    CHECK(e.scenes[1].variant.find('\n') == std::string::npos);
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

TEST_CASE("a scene variant's light_direction moves the first light, a directional sun, and a wrong one names its line") {
    test::TempFolder folder;
    folder.write("scene.toml", "[[light]]\ntype = \"directional\"\ndirection = [0, -1, 0]\n");
    folder.write("spot.toml", "[[light]]\ntype = \"spot\"\nposition = [0, 4, 0]\ndirection = [0, -1, 0]\n");
    const std::filesystem::path file = folder.write(
        "experiment.toml",
        "[experiment]\nscenes = [\"scene.toml\", { file = \"scene.toml\", name = \"low\", light_direction = [-3, -0.3, 0] }]\n"
        "[[technique]]\nname = \"shadow.hard\"\n");
    const Experiment e = load_experiment(file, TechniqueRegistry::instance());
    REQUIRE(e.scenes.size() == 2);
    CHECK(e.scenes[0].lights.at(0).direction == glm::vec3(0, -1, 0));
    const glm::vec3 low = e.scenes[1].lights.at(0).direction;
    CHECK(glm::length(low) == doctest::Approx(1.0f));
    CHECK(low.x == doctest::Approx(-3.0 / std::sqrt(9.09)));
    CHECK(low.y == doctest::Approx(-0.3 / std::sqrt(9.09)));
    for (const auto& [variant, words] : std::vector<std::pair<std::string, std::string>>{
             {"{ file = \"scene.toml\", name = \"v\", light_direction = [0, 0, 0] }", "zero vector"},
             {"{ file = \"scene.toml\", name = \"v\", light_direction = 1 }", "light_direction"},
             {"{ file = \"spot.toml\", name = \"v\", light_direction = [0, -1, 0] }", "not directional"}}) {
        CAPTURE(variant);
        const std::filesystem::path bad = folder.write(
            "bad.toml", "[experiment]\nscenes = [\n  \"scene.toml\",\n  " + variant + ",\n]\n[[technique]]\nname = \"shadow.hard\"\n");
        const auto error = test::config_error_of([&] { load_experiment(bad, TechniqueRegistry::instance()); });
        REQUIRE(error.has_value());
        CAPTURE(error->formatted());
        CHECK(error->line() == 4);
        CHECK(test::contains(error->formatted(), words));
    }
}

TEST_CASE("a scene variant's populations = { name = { ... } } replaces those parameters and generates the copies again") {
    test::TempFolder folder;
    folder.write("scene.toml",
                 "[[light]]\ntype = \"directional\"\n[[population]]\nname = \"grass\"\nkind = \"grass\"\n"
                 "params = { cells_x = 3, cells_z = 2, blades = 40 }\n");
    const std::filesystem::path file = folder.write(
        "experiment.toml",
        "[experiment]\nscenes = [\"scene.toml\", { file = \"scene.toml\", name = \"quick\", populations = { grass = { "
        "blades = 10, width_min = 0.02, width_max = 0.04 } } }]\n[[technique]]\nname = \"grass.geometry\"\n");
    const Experiment e = load_experiment(file, TechniqueRegistry::instance());
    REQUIRE(e.scenes.size() == 2);
    const Population& full = e.scenes[0].populations.at(0);
    const Population& quick = e.scenes[1].populations.at(0);
    CHECK(full.params.integer("blades") == 40);
    CHECK(quick.params.integer("blades") == 10);
    CHECK(quick.params.real("width_max") == doctest::Approx(0.04));
    CHECK(quick.params.integer("cells_x") == 3);  // kept
    REQUIRE(full.family);
    REQUIRE(quick.family);
    CHECK(quick.family->instances.size() == 6);
    CHECK(quick.family->prototype.triangle_count() * 4 == full.family->prototype.triangle_count());

    const auto error_of = [&](const std::string& populations) {
        const std::filesystem::path bad = folder.write(
            "bad.toml", "[experiment]\nscenes = [\n  { file = \"scene.toml\", name = \"v\", populations = " + populations +
                            " },\n]\n[[technique]]\nname = \"grass.geometry\"\n");
        return test::config_error_of([&] { load_experiment(bad, TechniqueRegistry::instance()); });
    };
    for (const auto& [populations, words] : std::vector<std::pair<std::string, std::string>>{
             {"{ gras = { blades = 10 } }", "did you mean 'grass'"},
             {"{ grass = { blades = 0 } }", "blades"},
             {"{ grass = { bladez = 10 } }", "bladez"},
             {"{ grass = { width_min = 0.5, width_max = 0.1 } }", "cannot be generated"}}) {
        CAPTURE(populations);
        const auto error = error_of(populations);
        REQUIRE(error.has_value());
        CAPTURE(error->formatted());
        CHECK(error->line() == 3);
        CHECK(test::contains(error->formatted(), words));
    }
}
