// Parameter combinations the shadow techniques refuse although each value is valid alone, found
// when a config's cases are expanded (before anything runs or is written): the error names the
// file and the line of the value to change, and the safe range.
#include "config/experiment_config.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/text_search.hpp"
#include "../shaders/shadow_filtering.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

using namespace canopy;
using test::contains;

namespace {

// The error expanding the cases of an experiment with `technique_block` over a one-light scene
// raises, or nothing. The experiment file's lines: 1 [experiment], 2 scenes, then the block.
std::optional<ConfigError> expansion_error(const std::string& technique_block) {
    const test::TempFolder folder("canopy-test-conflicts");
    folder.write("room.toml", "[scene]\nname = \"room\"\n[[light]]\ntype = \"directional\"\n");
    const std::filesystem::path file =
        folder.write("experiment.toml", "[experiment]\nscenes = [\"room.toml\"]\n" + technique_block);
    return test::config_error_of(
        [&] { expand_cases(load_experiment(file, TechniqueRegistry::instance()), TechniqueRegistry::instance()); });
}

}  // namespace

// exp(c z) stored linearly overflows fp16 above c = ln 65504 = 11.09 and fp32 (with the prefilter's
// sums) above ~84.6: the map holds inf, the lit pass reads FLT_MAX, and every shadow vanishes.
TEST_CASE("shadow.esm refuses exponents its linear storage cannot hold") {
    // fp16 with the default exponent 80: the line of `precision`, the safe range in the hint.
    const auto fp16_default = expansion_error("[[technique]]\nname = \"shadow.esm\"\n[technique.params]\nprecision = \"fp16\"\n");
    REQUIRE(fp16_default);
    CHECK(fp16_default->line() == 6);  // precision = "fp16"
    CHECK(fp16_default->file().filename() == "experiment.toml");
    CHECK(contains(fp16_default->what(), "shadow.esm"));
    CHECK(contains(fp16_default->what(), "exponent 80 overflows fp16"));
    CHECK(contains(fp16_default->hint(), "[1, 11]"));
    CHECK(contains(fp16_default->hint(), "log_space = true"));
    CHECK(contains(fp16_default->formatted(), "experiment.toml:6: error:"));
    // The exponent's own line when the config gives it (first among the conflicting parameters).
    const auto both = expansion_error(
        "[[technique]]\nname = \"shadow.esm\"\n[technique.params]\nprecision = \"fp16\"\nexponent = 12.0\n");
    REQUIRE(both);
    CHECK(both->line() == 7);
    // A sweep: only the fp16 case conflicts, and it is found.
    const auto sweep = expansion_error(
        "[[technique]]\nname = \"shadow.esm\"\n[technique.params]\nprecision = [\"fp32\", \"fp16\"]\n");
    REQUIRE(sweep);
    CHECK(sweep->line() == 6);
    // fp32 past its bound.
    const auto fp32 = expansion_error("[[technique]]\nname = \"shadow.esm\"\n[technique.params]\nexponent = 85\n");
    REQUIRE(fp32);
    CHECK(contains(fp32->hint(), "[1, 84]"));
    // Accepted: inside the bounds, and any exponent in log space.
    CHECK_FALSE(expansion_error("[[technique]]\nname = \"shadow.esm\"\n[technique.params]\nprecision = \"fp16\"\nexponent = 11\n"));
    CHECK_FALSE(expansion_error("[[technique]]\nname = \"shadow.esm\"\n[technique.params]\nexponent = 84\n"));
    CHECK_FALSE(expansion_error(
        "[[technique]]\nname = \"shadow.esm\"\n[technique.params]\nprecision = \"fp16\"\nlog_space = true\nexponent = 200\n"));
    CHECK_FALSE(expansion_error("[[technique]]\nname = \"shadow.esm\"\n"));  // the defaults: fp32, c = 80
}

// The bounds themselves: exp(c) and the prefilter's largest sum (63 texels) fit at the bound.
TEST_CASE("ESM exponent bounds fit their storage") {
    using shader::esm_max_exponent;
    CHECK(std::exp(esm_max_exponent(true)) <= 65504.0f);
    CHECK(std::exp(11.1f) > 65504.0f);
    CHECK(std::isfinite(63.0f * std::exp(esm_max_exponent(false))));
}
