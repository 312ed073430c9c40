// Scene and experiment names become file names, case ids and output folders: a name that could
// escape the run folder, hide a file or garble a terminal is refused at load, while names in
// any script keep readable ids.
#include "config/experiment_config.hpp"
#include "config/file_name_rules.hpp"
#include "config/scene_config.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

using namespace canopy;
using test::config_error_of;
using test::contains;

namespace {

const std::string kLight = "[[light]]\ntype = \"directional\"\n";

}  // namespace

TEST_CASE("names that leave a folder, hide a file or hold unreadable characters are refused") {
    for (const char* bad : {"../../../x", "a/b", "a\\b", "..", "a..b", ".hidden", "-rf", "my scene", "tab\there",
                            "line\nbreak", "\x1b[31mred", "\xff\xfe", "\xc0\xaf", "zero\xe2\x80\x8bwidth",
                            "nb\xc2\xa0space", "fraction\xe2\x81\x84slash", "a:b", "a*b", "a?b", "a\"b", ""}) {
        CAPTURE(bad);
        CHECK(file_name_problem(bad));
    }
    CHECK(file_name_problem(std::string(kMaxNameBytes + 1, 'a')));
    for (const char* good : {"spheres", "at-at_2.5", "forêt", "森の木", "Ελληνικά", "ünïcödé-42", "x.y"}) {
        CAPTURE(good);
        CHECK(!file_name_problem(good));
    }
    CHECK(!file_name_problem(std::string(kMaxNameBytes, 'a')));
}

TEST_CASE("file_name_safe keeps readable characters and replaces the rest") {
    CHECK(file_name_safe("forêt_森 x/y") == "forêt_森-x-y");
    CHECK(file_name_safe("bad\xffutf8") == "bad-utf8");
    CHECK(file_name_safe("ctrl\x1b") == "ctrl-");
}

TEST_CASE("printable_name escapes control characters for messages") {
    CHECK(printable_name("\x1b[31m") == "'\\x1b[31m'");
    CHECK(printable_name("forêt") == "'forêt'");
    CHECK(printable_name(std::string(1000, 'a')).size() < 200);
}

TEST_CASE("a scene name such as ../../../x is refused at its line") {
    // Before: the reference's images were written outside the run folder.
    const auto error = config_error_of([] { parse_scene("[scene]\nname = \"../../../x\"\n" + kLight, "s.toml"); });
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(error->line() == 2);
    CHECK(contains(error->what(), "'..'"));
    CHECK(contains(error->hint(), "letters of any script"));
}

TEST_CASE("a scene without a name whose file name cannot be one is told to add a name") {
    const auto error = config_error_of([] { parse_scene(kLight, "my scene.toml"); });
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(contains(error->what(), "'my scene'"));
    CHECK(contains(error->hint(), "name = "));
}

TEST_CASE("experiment names and scene variant names follow the same rule") {
    test::TempFolder folder;
    folder.write("scene.toml", "[scene]\nname = \"room\"\n" + kLight);
    const std::string technique = "\n[[technique]]\nname = \"shadow.hard\"\n";
    const auto line_of = [&](const std::string& text) {
        const auto error = config_error_of([&] { load_experiment(folder.write("e.toml", text), TechniqueRegistry::instance()); });
        if (error) INFO(error->formatted());
        return error ? error->line() : -1;
    };
    CHECK(line_of("[experiment]\nname = \"../escape\"\nscenes = [\"scene.toml\"]\n" + technique) == 2);
    CHECK(line_of("[experiment]\nname = \"ok\"\nscenes = [{ file = \"scene.toml\", name = \"a/b\" }]\n" + technique) == 3);
    CHECK(line_of("[experiment]\nname = \"ok\"\nscenes = [{ file = \"scene.toml\", name = \"forêt\" }]\n" + technique) == -1);

    // A file name that cannot be an experiment name, with no name key.
    const auto error = config_error_of([&] {
        load_experiment(folder.write(".hidden.toml", "[experiment]\nscenes = [\"scene.toml\"]\n" + technique),
                        TechniqueRegistry::instance());
    });
    REQUIRE(error);
    CHECK(contains(error->hint(), "name = "));
}

TEST_CASE("case ids stay short enough for file names, and distinct") {
    // A 100-byte scene name and every parameter of a technique spelled out: the id would exceed
    // the 255 bytes of a file name, and "<id>.error.png" could not be written.
    test::TempFolder folder;
    folder.write("scene.toml", "[scene]\nname = \"" + std::string(kMaxNameBytes, 's') + "\"\n" + kLight);
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    for (const Technique* technique : registry.all()) {
        CAPTURE(technique->name());
        std::string params;
        for (const ParamSpec& spec : technique->params())
            params += spec.name + " = " +
                      (std::holds_alternative<std::string>(spec.default_value) ? "\"" + to_string(spec.default_value) + "\""
                                                                               : to_string(spec.default_value)) +
                      "\n";
        // Two cases differing only in the last parameters' values must keep different ids.
        const std::filesystem::path file = folder.write(
            "e.toml", "[experiment]\nname = \"long\"\nscenes = [\"scene.toml\"]\nresolutions = [[8192, 8192], [8191, 8192]]\n"
                      "[[technique]]\nname = \"" + technique->name() + "\"\n[technique.params]\n" + params);
        const std::vector<Case> cases = expand_cases(load_experiment(file, registry), registry);
        REQUIRE(cases.size() == 2);
        for (const Case& c : cases) {
            CAPTURE(c.id);
            CHECK(c.id.size() + std::string(".error.png").size() <= 255);
            CHECK(!file_name_problem(c.id.substr(0, kMaxNameBytes)));
        }
        CHECK(cases[0].id != cases[1].id);
    }
}
