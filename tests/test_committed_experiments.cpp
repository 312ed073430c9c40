// The committed experiments (configs/experiments/**) agree on how they make their references, and
// the shadow-free scene variants they use to check the technique-isolated error are what they say.
#include "config/experiment_config.hpp"
#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "scene/population_kind.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"

#include "support/technique_variants.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <set>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

const fs::path kExperiments = fs::path(CANOPY_SOURCE_DIR) / "configs" / "experiments";
const fs::path kScenes = fs::path(CANOPY_SOURCE_DIR) / "configs" / "scenes";

std::vector<fs::path> committed_experiments() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kExperiments))
        if (entry.is_regular_file() && entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST_CASE("every committed experiment of a family makes its reference with the family's settings") {
    // configs/README.md, [reference]: whole-image errors move by 8-12 % between 2 and 4 pixel
    // samples, so tables made with different settings would not compare. The grass experiments
    // take 64 pixel samples (a blade is thinner than a pixel), the others 4.
    const auto files = committed_experiments();
    REQUIRE(files.size() >= 10);  // default, checks/shadow-free and the eight paper experiments
    int grass = 0;
    for (const fs::path& file : files) {
        CAPTURE(file.string());
        const Experiment experiment = load_experiment(file, TechniqueRegistry::instance());
        bool grass_family = false;
        for (const auto& t : experiment.techniques) grass_family = grass_family || t.name.rfind("grass.", 0) == 0;
        grass += grass_family;
        CHECK(experiment.reference_enabled);
        CHECK(experiment.reference.light_samples == 64);
        CHECK(experiment.reference.pixel_samples == (grass_family ? 64 : 4));
        CHECK(experiment.reference.seed == 1);
    }
    CHECK(grass >= 13);
}

TEST_CASE("grass/representations.toml: the meadow in the local and the shadowed reference mode") {
    const Experiment experiment =
        load_experiment(kExperiments / "grass" / "representations.toml", TechniqueRegistry::instance());
    REQUIRE(experiment.scenes.size() == 2);
    CHECK(experiment.scenes[0].name == "meadow");
    CHECK(experiment.scenes[0].shadow_light() == nullptr);  // local: the sun casts no shadows
    CHECK(experiment.scenes[1].name == "meadow-shadowed");
    REQUIRE(experiment.scenes[1].shadow_light() != nullptr);
    CHECK(experiment.scenes[1].lights.front().casts_shadows);
    // The same field in both.
    CHECK(experiment.scenes[1].populations.at(0).params.summary() == experiment.scenes[0].populations.at(0).params.summary());
}

TEST_CASE("a scene variant with casts_shadows = false: no object casts a shadow, the light still does") {
    const test::TempFolder folder;
    const fs::path file = folder.write(
        "experiment.toml",
        "[experiment]\nscenes = [\n"
        "  { file = \"" + (kScenes / "chairs.toml").string() + "\", name = \"free\", casts_shadows = false },\n"
        "  { file = \"" + (kScenes / "chairs.toml").string() + "\", name = \"kept\", casts_shadows = true },\n"
        "]\n[[technique]]\nname = \"shadow.hard\"\n");
    const Experiment experiment = load_experiment(file, TechniqueRegistry::instance());
    REQUIRE(experiment.scenes.size() == 2);
    const Scene& free = experiment.scenes[0];
    CHECK(free.name == "free");
    REQUIRE(free.objects.size() > 10);
    for (const Object& object : free.objects) CHECK_FALSE(object.casts_shadows);
    REQUIRE(free.shadow_light() != nullptr);  // techniques still have a light to shadow
    for (const Object& object : experiment.scenes[1].objects) CHECK(object.casts_shadows);

    const fs::path wrong = folder.write(
        "wrong.toml", "[experiment]\nscenes = [\n  { file = \"" + (kScenes / "chairs.toml").string() +
                          "\", casts_shadows = \"no\" },\n]\n[[technique]]\nname = \"shadow.hard\"\n");
    const auto error = test::config_error_of([&] { load_experiment(wrong, TechniqueRegistry::instance()); });
    REQUIRE(error);
    CHECK(error->line() == 3);
    CHECK(std::string(error->what()).find("casts_shadows") != std::string::npos);
}

TEST_CASE("checks/shadow-free.toml: every committed shadow scene without shadows, under every shadow technique") {
    const Experiment experiment =
        load_experiment(kExperiments / "checks" / "shadow-free.toml", TechniqueRegistry::instance());
    // The shadow family's scenes: those without a population of a family's kind (grass fields).
    std::set<std::string> scene_files;
    for (const auto& entry : fs::directory_iterator(kScenes)) {
        if (entry.path().extension() != ".toml") continue;
        const Scene scene = load_scene(entry.path());
        if (std::none_of(scene.populations.begin(), scene.populations.end(), [](const Population& p) { return bool(p.family); }))
            scene_files.insert(entry.path().stem().string());
    }
    CHECK(scene_files.count("spheres") == 1);
    std::set<std::string> variants;
    for (const Scene& scene : experiment.scenes) {
        CAPTURE(scene.name);
        variants.insert(scene.file.stem().string());
        for (const Object& object : scene.objects) CHECK_FALSE(object.casts_shadows);
    }
    CHECK(variants == scene_files);
    std::set<std::string> techniques, registered;
    for (const TechniqueEntry& entry : experiment.techniques) techniques.insert(entry.name);
    for (const Technique* t : test::family_techniques("shadow")) registered.insert(t->name());
    CHECK(techniques == registered);
}

TEST_CASE("paper/l-t7.1.toml: Lemme's Table 7.1 field and settings") {
    // 32 x 32 cells of 2400 blades at 10 triangles (L1026-1035: 24.6 M triangles), the volume at
    // 16 slices of 1024 x 128, the image at 1024^2 (L1036).
    const Experiment experiment = load_experiment(kExperiments / "paper" / "l-t7.1.toml", TechniqueRegistry::instance());
    REQUIRE(experiment.scenes.size() == 1);
    const Population& field = experiment.scenes[0].populations.at(0);
    REQUIRE(field.family);
    CHECK(field.family->instances.size() == 1024);
    CHECK(field.family->prototype.triangle_count() == 24000);
    CHECK(experiment.scenes[0].shadow_light() == nullptr);  // local mode
    REQUIRE(experiment.techniques.size() == 3);
    CHECK(experiment.techniques[0].name == "grass.geometry");
    CHECK(experiment.techniques[1].name == "grass.volume");
    CHECK(std::get<long long>(experiment.techniques[1].sweep.at("slices").at(0)) == 16);
    CHECK(std::get<long long>(experiment.techniques[1].sweep.at("resolution").at(0)) == 1024);
    CHECK(std::get<long long>(experiment.techniques[1].sweep.at("height_resolution").at(0)) == 128);
    CHECK(std::get<long long>(experiment.techniques[2].sweep.at("resolution").at(0)) == 1024);
}

TEST_CASE("paper/l-t7.2.toml: Lemme's Table 7.2 macro sizes on the Table 7.1 field") {
    // The same field and representations as L-T7.1, each at macro-cells of 1, 2, 4, 8 and 16 (L1047)
    // and, as L-T7.1 draws them, one instance per cell (0).
    const Experiment experiment = load_experiment(kExperiments / "paper" / "l-t7.2.toml", TechniqueRegistry::instance());
    const Experiment t71 = load_experiment(kExperiments / "paper" / "l-t7.1.toml", TechniqueRegistry::instance());
    REQUIRE(experiment.scenes.size() == 1);
    CHECK(experiment.scenes[0].name == t71.scenes[0].name);
    REQUIRE(experiment.techniques.size() == 2);
    const std::vector<ParamValue> sizes{0LL, 1LL, 2LL, 4LL, 8LL, 16LL};
    for (const TechniqueEntry& entry : experiment.techniques) {
        CAPTURE(entry.name);
        CHECK(entry.sweep.at("macro_cells") == sizes);
        for (const TechniqueEntry& same : t71.techniques)
            if (same.name == entry.name)
                for (const auto& [name, values] : same.sweep) CHECK(entry.sweep.at(name) == values);
    }
    CHECK(experiment.techniques[0].name == "grass.volume");
    CHECK(experiment.techniques[1].name == "grass.image");
}
