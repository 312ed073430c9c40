// The table `canopy run` prints: compact enough for a terminal (about 120 columns) — technique,
// parameters, GPU time, ratio and the key errors, one table per scene and resolution. results.md
// keeps every column.
#pragma once

#include "run/case_result.hpp"

#include <string>

namespace canopy {

inline constexpr size_t kConsoleParametersWidth = 32;  // longer parameter lists end in "…"

std::string console_table(const RunRecord& run);

}  // namespace canopy
