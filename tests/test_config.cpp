// Scene and experiment config loading: valid files load completely, and every kind of mistake
// is reported with the right file, line and hint.
#include "config/experiment_config.hpp"
#include "config/scene_config.hpp"
#include "config/toml_reader.hpp"
#include "core/error.hpp"
#include "core/param.hpp"
#include "core/registry.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <optional>

using namespace canopy;
using test::config_error_of;
using test::contains;

namespace {

const std::filesystem::path kData = std::filesystem::path(CANOPY_TEST_DATA) / "config";

// A technique with one parameter of each type, registered under a name no real technique uses.
class FakeTechnique : public Technique {
public:
    std::string name() const override { return "test.fake"; }
    std::string summary() const override { return "fake technique for config tests"; }
    std::string paper() const override { return "none"; }
    std::vector<ParamSpec> params() const override {
        return {
            ParamSpec::integer("kernel", 5, 1, 11, "filter width in texels"),
            ParamSpec::choice("pattern", "grid", {"grid", "poisson"}, "sample pattern"),
            ParamSpec::real("bias", 0.005, 0.0, 0.05, "depth bias"),
            ParamSpec::boolean("hardware_pcf", true, "use the depth-compare sampler"),
        };
    }
    FrameGraph graph(const ParamSet&) const override { return {}; }
    ErrorColumns error_columns() const override { return {}; }
};

const RegisterTechnique<FakeTechnique> registered_fake;

const std::vector<ParamSpec> kFakeSpecs = FakeTechnique().params();

std::optional<ConfigError> resolve_error(const std::string& name, ParamValue value) {
    return config_error_of([&] {
        ParamSet::resolve(kFakeSpecs, {{name, value}}, {{name, 14}}, {"experiment.toml", 10}, "test.fake");
    });
}

}  // namespace

TEST_CASE("ConfigError::formatted names file, line and hint") {
    CHECK(ConfigError("a.toml", 14, "bad value", "use 3").formatted() == "a.toml:14: error: bad value\n  hint: use 3");
    CHECK(ConfigError("a.toml", 0, "missing").formatted() == "a.toml: error: missing");
    CHECK(ConfigError("", 0, "plain").formatted() == "error: plain");
}

TEST_CASE("closest_match suggests only near words, case-insensitively") {
    const std::vector<std::string> keys{"position", "target", "up", "fov", "near", "far"};
    CHECK(closest_match("postion", keys) == "position");
    CHECK(closest_match("FOV", keys) == "fov");
    CHECK(closest_match("nera", keys) == "near");
    CHECK(closest_match("brightness", keys) == "");
    CHECK(closest_match("x", {}) == "");
}

TEST_CASE("ParamSpec::type_and_range and to_string") {
    CHECK(kFakeSpecs[0].type_and_range() == "int in [1, 11]");
    CHECK(kFakeSpecs[1].type_and_range() == "one of grid|poisson");
    CHECK(kFakeSpecs[2].type_and_range() == "float in [0, 0.05]");
    CHECK(kFakeSpecs[3].type_and_range() == "bool");
    CHECK(to_string(ParamValue{7LL}) == "7");
    CHECK(to_string(ParamValue{0.005}) == "0.005");
    CHECK(to_string(ParamValue{2.0}) == "2");
    CHECK(to_string(ParamValue{false}) == "false");
    CHECK(to_string(ParamValue{std::string("poisson")}) == "poisson");
}

TEST_CASE("a default or range declared from a float constant reads as written, not as float noise") {
    // Before: `canopy list` showed 0.15f's double, 0.15000000596046448.
    const ParamSpec from_float = ParamSpec::real("width", 0.15f, 0.1f, 2.7f, "a float constant");
    CHECK(default_text(from_float) == "0.15");
    CHECK(from_float.type_and_range() == "float in [0.1, 2.7]");
    const ParamSpec from_double = ParamSpec::real("bias", 0.15, 0.0, 0.3333333333333333, "a double constant");
    CHECK(default_text(from_double) == "0.15");
    CHECK(from_double.type_and_range() == "float in [0, 0.3333333333333333]");
}

TEST_CASE("ParamSet::resolve fills defaults and applies given values") {
    const ParamSet defaults = ParamSet::resolve(kFakeSpecs, {}, {}, {}, "test.fake");
    CHECK(defaults.summary() == "kernel=5 pattern=grid bias=0.005 hardware_pcf=true");

    const ParamSet given = ParamSet::resolve(
        kFakeSpecs, {{"kernel", 7LL}, {"bias", 0LL}, {"pattern", std::string("poisson")}, {"hardware_pcf", false}}, {},
        {}, "test.fake");
    CHECK(given.integer("kernel") == 7);
    CHECK(given.real("bias") == 0.0);  // an integer is accepted for a real
    CHECK(given.choice("pattern") == "poisson");
    CHECK(given.boolean("hardware_pcf") == false);
    REQUIRE(given.values().size() == 4);
    CHECK(given.values()[0].first == "kernel");

    CHECK_THROWS_AS(given.integer("bias"), std::logic_error);  // wrong type
    CHECK_THROWS_AS(given.real("nope"), std::logic_error);     // wrong name
}

TEST_CASE("a path parameter is taken from the folder of the file that gives it, and must name a file") {
    test::TempFolder folder;
    folder.write("maps/a.png", "not really a png");
    const std::vector<ParamSpec> specs{ParamSpec::path("map", "a map")};
    CHECK(specs[0].type_and_range() == "file path");
    const SourceLocation where{folder.path() / "scenes" / "scene.toml", 3};
    CHECK(ParamSet::resolve(specs, {}, {}, where, "test").path("map").empty());  // default: none
    const ParamSet given = ParamSet::resolve(specs, {{"map", std::string("../maps/a.png")}}, {}, where, "test");
    CHECK(std::filesystem::path(given.path("map")) == std::filesystem::absolute(folder.path() / "maps" / "a.png").lexically_normal());
    // Resolved again (an experiment's population override), an absolute path stays.
    CHECK(ParamSet::resolve(specs, {{"map", given.path("map")}}, {}, {}, "test").path("map") == given.path("map"));
    const auto missing = test::config_error_of(
        [&] { ParamSet::resolve(specs, {{"map", std::string("../maps/b.png")}}, {{"map", 7}}, where, "test"); });
    REQUIRE(missing);
    CHECK(missing->line() == 7);
    CHECK(contains(missing->what(), "names '../maps/b.png', which is not a file"));
    CHECK(contains(missing->hint(), "relative path is taken from the folder of scene.toml"));
    const auto folder_given = test::config_error_of(
        [&] { ParamSet::resolve(specs, {{"map", std::string("../maps")}}, {}, where, "test"); });
    CHECK(folder_given);
    const auto number = test::config_error_of([&] { ParamSet::resolve(specs, {{"map", 3LL}}, {}, where, "test"); });
    REQUIRE(number);
    CHECK(contains(number->what(), "must be a file path in quotes"));
}

TEST_CASE("ParamSet::resolve explains every kind of bad value") {
    SUBCASE("unknown name, with suggestion and the parameter list") {
        const auto error = resolve_error("kernal", 5LL);
        REQUIRE(error);
        CHECK(error->formatted() ==
              "experiment.toml:14: error: test.fake: parameter 'kernal' is unknown\n"
              "  hint: did you mean 'kernel'? parameters of test.fake: kernel, pattern, bias, hardware_pcf");
    }
    SUBCASE("out of range") {
        const auto error = resolve_error("kernel", 40LL);
        REQUIRE(error);
        CHECK(error->line() == 14);
        CHECK(contains(error->what(), "value 40 is out of range for 'kernel' (int in [1, 11])"));
        CHECK(error->hint() == "use a value in [1, 11]");
        CHECK(resolve_error("bias", 0.5));
        CHECK(resolve_error("bias", std::nan("")));
        CHECK_FALSE(resolve_error("bias", 0.05));
    }
    SUBCASE("a real for an integer is an error, even when integral") {
        const auto error = resolve_error("kernel", 5.0);
        REQUIRE(error);
        CHECK(contains(error->what(), "must be an integer"));
        CHECK(contains(error->hint(), "kernel = 5"));
    }
    SUBCASE("wrong types name the expected type") {
        const auto for_real = resolve_error("bias", std::string("small"));
        REQUIRE(for_real);
        CHECK(contains(for_real->what(), "must be a number"));
        const auto for_bool = resolve_error("hardware_pcf", 1LL);
        REQUIRE(for_bool);
        CHECK(contains(for_bool->what(), "must be a boolean"));
        const auto for_choice = resolve_error("pattern", 3LL);
        REQUIRE(for_choice);
        CHECK(contains(for_choice->what(), "must be a string"));
    }
    SUBCASE("a misspelled choice") {
        const auto error = resolve_error("pattern", std::string("poison"));
        REQUIRE(error);
        CHECK(contains(error->what(), "'poison' is not allowed for 'pattern'"));
        CHECK(contains(error->hint(), "did you mean 'poisson'?"));
    }
}

TEST_CASE("TechniqueRegistry finds, lists and refuses duplicates") {
    TechniqueRegistry& registry = TechniqueRegistry::instance();
    REQUIRE(registry.find("test.fake") != nullptr);
    CHECK(registry.find("test.fake")->name() == "test.fake");
    CHECK(registry.find("test.missing") == nullptr);
    const std::vector<std::string> names = registry.names();
    CHECK(std::is_sorted(names.begin(), names.end()));
    CHECK(std::find(names.begin(), names.end(), "test.fake") != names.end());
    CHECK(registry.all().size() == names.size());
    CHECK_THROWS_AS(registry.add(std::make_unique<FakeTechnique>()), std::logic_error);
}

TEST_CASE("a full scene loads every key") {
    const Scene scene = load_scene(kData / "scenes/full.toml");
    CHECK(scene.name == "full_scene");
    CHECK(scene.ambient == glm::vec3(0.05f));
    CHECK(scene.background == glm::vec3(0.1f, 0.2f, 0.3f));
    CHECK(scene.camera.position == glm::vec3(0, 3, 8));
    CHECK(scene.camera.target == glm::vec3(0, 0.5f, 0));
    CHECK(scene.camera.fov_y_degrees == 40.0f);
    CHECK(scene.camera.near_plane == doctest::Approx(0.1));
    CHECK(scene.camera.far_plane == 50.0f);

    REQUIRE(scene.lights.size() == 4);
    const Light& rect = scene.lights[0];
    CHECK(rect.type == LightType::rect);
    CHECK(rect.direction == glm::vec3(0, -1, 0));  // normalised
    CHECK(rect.rect_size == glm::vec2(2, 1));
    CHECK(rect.intensity == 40.0f);
    CHECK(rect.color == glm::vec3(1, 0.9f, 0.8f));
    CHECK(rect.where.line == 15);
    CHECK(rect.where.file == kData / "scenes/full.toml");
    const Light& directional = scene.lights[1];
    CHECK(directional.type == LightType::directional);
    CHECK_FALSE(directional.casts_shadows);
    CHECK(glm::length(directional.direction) == doctest::Approx(1.0));
    CHECK(scene.lights[2].type == LightType::spot);
    CHECK(scene.lights[2].spot_angle_degrees == 25.0f);
    CHECK(scene.lights[3].type == LightType::sphere);
    CHECK(scene.lights[3].sphere_radius == 0.5f);
    CHECK(scene.lights[3].color == glm::vec3(0.5f));
    CHECK(scene.shadow_light() == &scene.lights[0]);

    REQUIRE(scene.objects.size() == 5);
    const Object& floor = scene.objects[0];
    CHECK(floor.name == "floor");
    CHECK(floor.shape == ShapeType::plane);
    CHECK(floor.plane_size == glm::vec2(20, 10));
    CHECK(floor.material.albedo == glm::vec3(0.5f));
    CHECK(floor.where.line == 42);
    const Object& box = scene.objects[1];
    CHECK(box.name == "box1");  // "<shape><index>"
    CHECK(box.box_size == glm::vec3(2.0f));
    CHECK_FALSE(box.casts_shadows);
    REQUIRE(box.instances.size() == 1);
    CHECK(box.instances[0].translate == glm::vec3(1, 1, 0));
    CHECK(box.instances[0].rotate_degrees == glm::vec3(0, 45, 0));
    const Object& ball = scene.objects[2];
    CHECK(ball.radius == 0.75f);
    CHECK(ball.segments == 16);
    CHECK(ball.instances[0].scale == glm::vec3(1, 2, 1));
    const Object& pillar = scene.objects[3];
    CHECK(pillar.shape == ShapeType::cylinder);
    CHECK(pillar.height == 2.0f);
    REQUIRE(pillar.instances.size() == 2);
    const glm::vec4 moved = pillar.instances[1].matrix() * glm::vec4(1, 0, 0, 1);
    // scale 0.5, rotate 90 about Y: (1,0,0) -> (0,0,-0.5), then translate by -2 in x.
    CHECK(moved.x == doctest::Approx(-2.0));
    CHECK(moved.z == doctest::Approx(-0.5));
    const Object& tetra = scene.objects[4];
    CHECK(tetra.shape == ShapeType::mesh);
    CHECK(tetra.mesh_file.is_absolute());
    CHECK(tetra.mesh_file == std::filesystem::absolute(kData / "meshes/tetrahedron.obj").lexically_normal());
}

TEST_CASE("a minimal scene takes the documented defaults") {
    const Scene scene = load_scene(kData / "scenes/minimal.toml");
    CHECK(scene.name == "minimal");  // the file stem
    const Camera defaults;
    CHECK(scene.camera.position == defaults.position);
    CHECK(scene.camera.fov_y_degrees == defaults.fov_y_degrees);
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].intensity == Light{}.intensity);
    CHECK(scene.objects.empty());
}

TEST_CASE("malformed TOML reports its line") {
    const auto error = config_error_of([] { load_scene(kData / "scenes/malformed.toml"); });
    REQUIRE(error);
    CHECK(error->line() == 6);
    CHECK(contains(error->what(), "malformed TOML"));
    CHECK(contains(error->formatted(), "malformed.toml:6: error:"));
}

TEST_CASE("a missing config file is an error without a line, with a hint") {
    const auto error = config_error_of([] { load_scene(kData / "scenes/no_such_scene.toml"); });
    REQUIRE(error);
    CHECK(error->line() == 0);
    CHECK(contains(error->what(), "not found"));
    CHECK_FALSE(error->hint().empty());
}

TEST_CASE("a misspelled key names its line and suggests the right key") {
    const auto error = config_error_of([] { load_scene(kData / "scenes/misspelled_key.toml"); });
    REQUIRE(error);
    CHECK(error->line() == 3);
    CHECK(contains(error->what(), "unknown key 'postion' in [camera]"));
    CHECK(contains(error->hint(), "did you mean 'position'?"));
}

TEST_CASE("a misspelled table name is reported") {
    const auto error = config_error_of([] { parse_scene("[[lights]]\ntype = \"rect\"\n", "s.toml"); });
    REQUIRE(error);
    CHECK(error->line() == 1);
    CHECK(contains(error->what(), "unknown table [[lights]]"));
    CHECK(contains(error->hint(), "did you mean 'light'?"));
}

TEST_CASE("a wrong type names the expected type") {
    const auto error = config_error_of([] { load_scene(kData / "scenes/wrong_type.toml"); });
    REQUIRE(error);
    CHECK(error->line() == 2);
    CHECK(contains(error->what(), "'fov' in [camera] must be a number, got the string \"wide\""));
    CHECK(contains(error->hint(), "fov = 45"));
}

TEST_CASE("an out-of-range value names its line and the range") {
    const auto error = config_error_of([] { load_scene(kData / "scenes/out_of_range.toml"); });
    REQUIRE(error);
    CHECK(error->line() == 4);
    CHECK(contains(error->what(), "(0, 89]"));
}

TEST_CASE("a key that does not apply to the shape says which shapes use it") {
    const auto error = config_error_of([] { load_scene(kData / "scenes/radius_on_box.toml"); });
    REQUIRE(error);
    CHECK(error->line() == 7);
    CHECK(contains(error->what(), "'radius' in [[object]] #1 does not apply to box shapes"));
    CHECK(contains(error->hint(), "sphere and cylinder"));

    const auto light_error =
        config_error_of([] { parse_scene("[[light]]\ntype = \"sphere\"\nsize = [1, 1]\n", "s.toml"); });
    REQUIRE(light_error);
    CHECK(light_error->line() == 3);
    CHECK(contains(light_error->hint(), "rect lights"));
}

TEST_CASE("a missing mesh file names the file key's line") {
    const auto error = config_error_of([] { load_scene(kData / "scenes/missing_mesh.toml"); });
    REQUIRE(error);
    CHECK(error->file() == kData / "scenes/missing_mesh.toml");
    CHECK(error->line() == 7);
    CHECK(contains(error->what(), "meshes/does_not_exist.glb"));
    CHECK(contains(error->formatted(), "missing_mesh.toml:7: error:"));
}

TEST_CASE("scene value checks") {
    auto error_line = [](const std::string& text) {
        const auto error = config_error_of([&] { parse_scene(text, "s.toml"); });
        return error ? error->line() : -1;
    };
    const std::string light = "[[light]]\ntype = \"directional\"\n";
    CHECK(error_line("") == 0);                                             // no light at all
    CHECK(error_line("[[light]]\nintensity = 3\n") == 1);                   // type is required
    CHECK(error_line("[[light]]\ntype = \"spott\"\n") == 2);                // unknown type
    CHECK(error_line("[[light]]\ntype = \"spot\"\ndirection = [0, 0, 0]\n") == 3);
    CHECK(error_line("[[light]]\ntype = \"rect\"\ndirection = [0, 0, -1]\n") == 3);  // parallel to default up
    CHECK(error_line(light + "[camera]\nnear = 1\nfar = 0.5\n") == 5);
    CHECK(error_line(light + "[camera]\nfov = 180\n") == 4);
    CHECK(error_line(light + "[camera]\nposition = 1\n") == 4);             // no broadcast for points
    CHECK(error_line(light + "[[object]]\nshape = \"box\"\nalbedo = 1.5\n") == 5);
    CHECK(error_line(light + "[[object]]\nshape = \"sphere\"\nsegments = 2\n") == 5);
    CHECK(error_line(light + "[[object]]\nshape = \"sphere\"\nsegments = 8.0\n") == 5);
    CHECK(error_line(light + "[[object]]\nshape = \"box\"\nscale = [1, 0, 1]\n") == 5);
    CHECK(error_line(light + "[[object]]\nshape = \"plane\"\nsize = [1, 2, 3]\n") == 5);
    CHECK(error_line(light + "[[object]]\nshape = \"mesh\"\n") == 3);       // file is required
    CHECK(error_line(light + "[[object]]\nshape = \"box\"\ninstances = [\n  { translate = [1, 0, 0] },\n"
                             "  { tranlate = [1, 0, 0] },\n]\n") == 7);     // unknown key inside an instance
    CHECK(error_line(light + "[[object]]\nshape = \"box\"\ninstances = []\n") == 5);
    CHECK(error_line(light + "[scene]\nambient = [0.1, 0.1]\n") == 4);
    CHECK(error_line(light + "[scene]\nambient = 0.1\nbackground = -1\n") == 5);
    CHECK(error_line(light + "[[object]]\nshape = \"box\"\nsize = 2\n") == -1);  // valid
}

TEST_CASE("TomlReader getters and finish") {
    const toml::table table = parse_toml("a = 1\nb = [1, 2, 3]\nc = \"x\"\nd = true\ne = 2.5\nf = [1, 2]\n", "t.toml");
    TomlReader reader(table, "t.toml", "[test]");
    CHECK(reader.get_float("a", 0.0) == 1.0);
    CHECK(reader.get_vec3("b", glm::vec3(0)) == glm::vec3(1, 2, 3));
    CHECK(reader.get_vec3("a", glm::vec3(0)) == glm::vec3(1));  // broadcast
    CHECK(reader.get_string("c", "") == "x");
    CHECK(reader.get_bool("d", false) == true);
    CHECK(reader.get_vec2("f", glm::vec2(0)) == glm::vec2(1, 2));
    CHECK(reader.get_int("missing", 7) == 7);
    CHECK_THROWS_AS(reader.get_int("e", 0), ConfigError);
    CHECK_THROWS_AS(reader.get_vec3("f", glm::vec3(0)), ConfigError);
    CHECK_THROWS_AS(reader.get_bool("c", false), ConfigError);
    CHECK_NOTHROW(reader.finish());

    const toml::table extra = parse_toml("alpha = 1\n\nbeta = 2\n", "t.toml");
    TomlReader partial(extra, "t.toml", "[test]");
    partial.get_float("alpha", 0.0);
    const auto error = config_error_of([&] { partial.finish(); });
    REQUIRE(error);
    CHECK(error->line() == 3);
    CHECK(contains(error->what(), "unknown key 'beta' in [test]"));
}

TEST_CASE("an experiment expands its sweep into ordered cases with unique ids") {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    const Experiment experiment = load_experiment(kData / "experiments/sweep.toml", registry);
    CHECK(experiment.name == "sweep");
    CHECK(experiment.description == "kernel and pattern sweep");
    CHECK(experiment.warmup_frames == 2);
    CHECK(experiment.rounds == 3);
    CHECK(experiment.frames_per_sample == kDefaultFramesPerSample);
    REQUIRE(experiment.scenes.size() == 1);
    CHECK(experiment.scenes[0].name == "minimal");
    REQUIRE(experiment.resolutions.size() == 2);
    CHECK(experiment.resolutions[1].width == 128);
    CHECK(experiment.resolutions[1].height == 64);
    REQUIRE(experiment.techniques.size() == 2);
    CHECK(experiment.techniques[0].where.line == 10);
    CHECK(experiment.techniques[0].param_lines.at("kernel") == 14);
    CHECK((experiment.techniques[0].param_order == std::vector<std::string>{"pattern", "kernel", "bias"}));
    CHECK(experiment.config_hash.size() == 16);

    const std::vector<Case> cases = expand_cases(experiment, registry);
    REQUIRE(cases.size() == 10);  // 2 resolutions x (2 patterns x 2 kernels + 1)
    CHECK(cases[0].id == "minimal_64x32_test.fake_pattern-grid_kernel-3_bias-0.01");
    CHECK(cases[1].id == "minimal_64x32_test.fake_pattern-grid_kernel-5_bias-0.01");
    CHECK(cases[2].id == "minimal_64x32_test.fake_pattern-poisson_kernel-3_bias-0.01");
    CHECK(cases[3].id == "minimal_64x32_test.fake_pattern-poisson_kernel-5_bias-0.01");
    CHECK(cases[4].id == "minimal_64x32_test.fake");
    CHECK(cases[5].id == "minimal_128x64_test.fake_pattern-grid_kernel-3_bias-0.01");
    CHECK(cases[5].resolution.width == 128);
    CHECK(cases[3].params.integer("kernel") == 5);
    CHECK(cases[3].params.choice("pattern") == "poisson");
    CHECK(cases[3].params.real("bias") == doctest::Approx(0.01));
    CHECK(cases[3].params.boolean("hardware_pcf") == true);  // default
    CHECK(cases[4].params.summary() == "kernel=5 pattern=grid bias=0.005 hardware_pcf=true");
    for (const Case& c : cases) CHECK(c.technique == "test.fake");
}

TEST_CASE("an unknown technique names its line and suggests a registered one") {
    const auto error = config_error_of(
        [] { load_experiment(kData / "experiments/unknown_technique.toml", TechniqueRegistry::instance()); });
    REQUIRE(error);
    CHECK(error->line() == 8);
    CHECK(contains(error->what(), "unknown technique 'test.fak'"));
    CHECK(contains(error->hint(), "did you mean 'test.fake'?"));
    CHECK(contains(error->hint(), "canopy list"));
}

TEST_CASE("an unknown technique parameter names its line and suggests one") {
    const auto error = config_error_of(
        [] { load_experiment(kData / "experiments/unknown_param.toml", TechniqueRegistry::instance()); });
    REQUIRE(error);
    CHECK(error->line() == 8);
    CHECK(contains(error->what(), "test.fake: parameter 'kernal' is unknown"));
    CHECK(contains(error->hint(), "did you mean 'kernel'?"));
}

TEST_CASE("an out-of-range technique parameter names the value's own line") {
    const auto error = config_error_of(
        [] { load_experiment(kData / "experiments/param_out_of_range.toml", TechniqueRegistry::instance()); });
    REQUIRE(error);
    CHECK(error->line() == 9);
    CHECK(contains(error->what(), "value 40 is out of range for 'kernel' (int in [1, 11])"));
    CHECK(error->hint() == "use a value in [1, 11]");
}

TEST_CASE("errors in a scene used by an experiment carry the scene file's location") {
    const auto error =
        config_error_of([] { load_experiment(kData / "experiments/bad_scene.toml", TechniqueRegistry::instance()); });
    REQUIRE(error);
    CHECK(error->file().filename() == "misspelled_key.toml");
    CHECK(error->line() == 3);
}

TEST_CASE("experiment value checks") {
    test::TempFolder folder;
    folder.write("scene.toml", "[[light]]\ntype = \"directional\"\n");
    auto error_line = [&](const std::string& text) {
        const std::filesystem::path file = folder.write("experiment.toml", text);
        const auto error = config_error_of([&] { load_experiment(file, TechniqueRegistry::instance()); });
        return error ? error->line() : -1;
    };
    const std::string technique = "\n[[technique]]\nname = \"test.fake\"\n";
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\n" + technique) == -1);  // valid
    CHECK(error_line("[experiment]\nname = \"x\"\n" + technique) == 1);                 // scenes required
    CHECK(error_line("[experiment]\nscenes = []\n" + technique) == 2);
    CHECK(error_line("[experiment]\nscenes = [\"nope.toml\"]\n" + technique) == 2);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\nresolutions = [[0, 10]]\n" + technique) == 3);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\nresolutions = [640, 360]\n" + technique) == 3);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\nrepetitions = 0\n" + technique) == 3);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\nwarmup = -1\n" + technique) == 3);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\nrepetitons = 3\n" + technique) == 3);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\n") == 0);                // no technique
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\n" + technique + "[technique.params]\nkernel = []\n") ==
          7);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\n" + technique + "[technique.params]\nkernel = 5.0\n") ==
          7);
    CHECK(error_line("[experiment]\nscenes = [\"scene.toml\"]\n" + technique + "parms = 1\n") == 6);
}

TEST_CASE("the same technique with the same parameters twice is refused at the second listing") {
    // Issue 36: identical cases were measured twice under one heading (ids ..._2).
    test::TempFolder folder;
    folder.write("room.toml", "[scene]\nname = \"room\"\n[[light]]\ntype = \"directional\"\n");
    const auto error_of = [&](const std::string& techniques) {
        const std::filesystem::path file =
            folder.write("experiment.toml", "[experiment]\nscenes = [\"room.toml\"]\n" + techniques);
        return test::config_error_of([&] { load_experiment(file, TechniqueRegistry::instance()); });
    };
    const auto twice = error_of("[[technique]]\nname = \"test.fake\"\n[[technique]]\nname = \"test.fake\"\n");
    REQUIRE(twice);
    CHECK(twice->line() == 5);
    CHECK(std::string(twice->what()).find("repeats the parameters of the [[technique]] at line 3") != std::string::npos);
    // A default given is the same case as the default left out (test.fake's kernel is 5).
    const auto with_default =
        error_of("[[technique]]\nname = \"test.fake\"\n[[technique]]\nname = \"test.fake\"\nparams = { kernel = 5 }\n");
    REQUIRE(with_default);
    CHECK(with_default->line() == 5);
    const auto in_one_list = error_of("[[technique]]\nname = \"test.fake\"\nparams = { kernel = [3, 3] }\n");
    REQUIRE(in_one_list);
    CHECK(in_one_list->line() == 3);
    CHECK(std::string(in_one_list->what()).find("gives the same parameters twice") != std::string::npos);
    // Other values are other cases.
    const std::filesystem::path file = folder.write(
        "experiment.toml", "[experiment]\nscenes = [\"room.toml\"]\n"
                           "[[technique]]\nname = \"test.fake\"\nparams = { kernel = [3, 7], pattern = \"poisson\" }\n"
                           "[[technique]]\nname = \"test.fake\"\n");
    const std::vector<Case> cases =
        expand_cases(load_experiment(file, TechniqueRegistry::instance()), TechniqueRegistry::instance());
    REQUIRE(cases.size() == 3);
    // Keys given on one line keep their order too.
    CHECK(cases[0].id == "room_640x360_test.fake_kernel-3_pattern-poisson");
    CHECK(cases[1].id == "room_640x360_test.fake_kernel-7_pattern-poisson");
    CHECK(cases[2].id == "room_640x360_test.fake");
}

TEST_CASE("case ids keep names in any script readable") {
    test::TempFolder folder;
    folder.write("room.toml", "[scene]\nname = \"forêt_森\"\n[[light]]\ntype = \"directional\"\n");
    const std::filesystem::path file = folder.write(
        "experiment.toml", "[experiment]\nscenes = [\"room.toml\"]\n[[technique]]\nname = \"test.fake\"\n");
    const std::vector<Case> cases =
        expand_cases(load_experiment(file, TechniqueRegistry::instance()), TechniqueRegistry::instance());
    REQUIRE(cases.size() == 1);
    CHECK(cases[0].id == "forêt_森_640x360_test.fake");
}

TEST_CASE("the config hash changes when a scene file changes") {
    test::TempFolder folder;
    const std::string scene_text = "[[light]]\ntype = \"directional\"\n";
    folder.write("scenes/room.toml", scene_text);
    const std::filesystem::path file = folder.write(
        "experiments/e.toml", "[experiment]\nscenes = [\"../scenes/room.toml\"]\n[[technique]]\nname = \"test.fake\"\n");
    const TechniqueRegistry& registry = TechniqueRegistry::instance();

    const std::string first = load_experiment(file, registry).config_hash;
    CHECK(first.size() == 16);
    CHECK(first.find_first_not_of("0123456789abcdef") == std::string::npos);
    CHECK(load_experiment(file, registry).config_hash == first);  // deterministic

    folder.write("scenes/room.toml", scene_text + "intensity = 4\n");
    const std::string second = load_experiment(file, registry).config_hash;
    CHECK(second != first);

    folder.write("scenes/room.toml", scene_text);
    CHECK(load_experiment(file, registry).config_hash == first);
}

TEST_CASE("fnv1a_64 matches the reference values") {
    CHECK(fnv1a_64("") == 0xcbf29ce484222325ull);
    CHECK(fnv1a_64("a") == 0xaf63dc4c8601ec8cull);
    CHECK(fnv1a_64("foobar") == 0x85944171f73967e8ull);
    CHECK(fnv1a_64("bar", fnv1a_64("foo")) == fnv1a_64("foobar"));
}
