// The report of `canopy bench stability`: stability.md (a table per case, the targets and whether
// each case reaches them, the environment and the load during every run) and stability.json (the
// same numbers, every run's ratio and CV).
#pragma once

#include "run/stability_bench.hpp"

#include <filesystem>
#include <string>

namespace canopy {

std::string stability_markdown(const StabilityResult& result);
std::string stability_json(const StabilityResult& result);
void write_stability_report(const std::filesystem::path& dir, const StabilityResult& result);

}  // namespace canopy
