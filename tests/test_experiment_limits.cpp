// Experiments whose sweeps multiply into more cases than could ever run are refused at load,
// before they are expanded (which took gigabytes and minutes).
#include "config/experiment_config.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

using namespace canopy;

namespace {

std::string values(int count) {
    std::string list = "[";
    for (int i = 0; i < count; ++i) list += (i ? ", " : "") + std::to_string(64 + i);
    return list + "]";
}

}  // namespace

TEST_CASE("a sweep of more than 100000 cases is refused at its [[technique]]") {
    const test::TempFolder folder("canopy-test-sweep");
    folder.write("scene.toml", "[[light]]\ntype = \"directional\"\n");
    const auto load = [&](const std::string& params) {
        const std::filesystem::path file =
            folder.write("e.toml", "[experiment]\nscenes = [\"scene.toml\"]\nresolutions = [[8, 8], [16, 16]]\n"
                                   "[[technique]]\nname = \"shadow.hard\"\n"
                                   "[[technique]]\nname = \"shadow.pcf\"\n[technique.params]\n" +
                                       params);
        return load_experiment(file, TechniqueRegistry::instance());
    };
    // 2 resolutions x (1 + 1000 x 50) = 100002 cases.
    try {
        load("resolution = " + values(1000) + "\nbias_constant = [" + [] {
            std::string list;
            for (int i = 0; i < 50; ++i) list += (i ? ", " : "") + std::to_string(0.0001 * i);
            return list;
        }() + "]\n");
        FAIL("expected a ConfigError");
    } catch (const ConfigError& error) {
        INFO(error.formatted());
        CHECK(error.line() == 6);
        CHECK(std::string(error.what()).find("more than 100000 cases") != std::string::npos);
    }
    // 2 x (1 + 1000 x 49) = 98002 cases: allowed (and counted, not expanded, by the check).
    const Experiment experiment = load("resolution = " + values(1000) + "\nbias_constant = [" + [] {
        std::string list;
        for (int i = 0; i < 49; ++i) list += (i ? ", " : "") + std::to_string(0.0001 * i);
        return list;
    }() + "]\n");
    CHECK(experiment.techniques.size() == 2);
}
