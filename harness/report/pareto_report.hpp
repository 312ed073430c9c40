// pareto.md: the Pareto fronts of a run (report/pareto.hpp) as tables, one per group and error
// axis, marking the configurations on the front and naming one that dominates each of the others.
#pragma once

#include "report/pareto.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

// The fronts of `run` on `metrics` (default_pareto_metrics(run) when empty); "" when the run
// measured no error.
std::string pareto_report(const RunRecord& run, const std::vector<std::string>& metrics = {});
void write_pareto_report(const std::filesystem::path& path, const RunRecord& run);

}  // namespace canopy
