// Running a family benchmark from the command line (family_benchmark.hpp): its parameters typed
// from text, the run on a device, the report printed and written with the environment.
#pragma once

#include "run/family_benchmark.hpp"

#include <filesystem>
#include <map>
#include <string>

namespace canopy {

// The parameters given as text on the command line (`--name value`), typed by their specs.
// Throws ConfigError naming the parameter and its type for a value that does not parse.
std::map<std::string, ParamValue> parse_benchmark_params(const std::vector<ParamSpec>& specs,
                                                         const std::map<std::string, std::string>& given);

// Runs `benchmark` on `scene_file` on `device` (`canopy bench <name>` finds its default scene); prints the Markdown
// and, with `out`, writes out/<name>.md and out/<name>.json (numbers, parameters, scene,
// environment) atomically. Returns the process exit code.
int run_family_benchmark(const FamilyBenchmark& benchmark, const std::filesystem::path& scene_file,
                         const std::map<std::string, std::string>& given, const std::string& device,
                         const std::filesystem::path& out);

}  // namespace canopy
