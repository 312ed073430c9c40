// results.csv: one row per case, full-precision numbers, for spreadsheets and scripts.
#pragma once

#include "run/case_result.hpp"

#include <filesystem>
#include <string>

namespace canopy {

std::string csv_report(const RunRecord& run);
void write_csv_report(const std::filesystem::path& path, const RunRecord& run);

}  // namespace canopy
