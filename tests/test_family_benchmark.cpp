// Family benchmarks (run/family_benchmark.hpp, family_benchmark_run.hpp): registered by name, their parameters typed from
// the command line's text with refusals that name the parameter and its type.
#include "core/error.hpp"
#include "run/family_benchmark_run.hpp"

#include <doctest/doctest.h>

using namespace canopy;

TEST_CASE("family benchmarks: command-line parameters are typed by their specs, bad ones refused by name") {
    const std::vector<ParamSpec> specs{ParamSpec::integer("size", 4, 1, 16, "a size"),
                                       ParamSpec::real("share", 0.5, 0.0, 1.0, "a share"),
                                       ParamSpec::boolean("bleed", false, "a switch"),
                                       ParamSpec::choice("filter", "box", {"box", "max"}, "a filter")};
    const auto values = parse_benchmark_params(specs, {{"size", "8"}, {"share", "0.25"}, {"bleed", "true"}, {"filter", "max"}});
    CHECK(std::get<long long>(values.at("size")) == 8);
    CHECK(std::get<double>(values.at("share")) == 0.25);
    CHECK(std::get<bool>(values.at("bleed")));
    CHECK(std::get<std::string>(values.at("filter")) == "max");
    CHECK(parse_benchmark_params(specs, {}).empty());
    const auto refusal = [&](const std::map<std::string, std::string>& given) {
        try {
            parse_benchmark_params(specs, given);
        } catch (const ConfigError& e) {
            return e.formatted();
        }
        return std::string();
    };
    CHECK(refusal({{"size", "8x"}}).find("--size 8x: expected int in [1, 16]") != std::string::npos);
    CHECK(refusal({{"size", ""}}).find("--size") != std::string::npos);
    CHECK(refusal({{"share", "half"}}).find("--share half") != std::string::npos);
    CHECK(refusal({{"bleed", "yes"}}).find("--bleed yes") != std::string::npos);
    CHECK(refusal({{"colour", "red"}}).find("unknown parameter --colour") != std::string::npos);
    // Ranges and choices are checked where a technique's are, by ParamSet::resolve.
    CHECK_THROWS_AS(ParamSet::resolve(specs, parse_benchmark_params(specs, {{"size", "99"}}), {}, {}, "bench"), ConfigError);
}
