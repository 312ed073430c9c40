// results.md and the console table: a readable, pasteable Markdown table per run.
#pragma once

#include "run/case_result.hpp"

#include <filesystem>
#include <string>

namespace canopy {

// The table alone (also what `canopy run` prints).
std::string markdown_table(const RunRecord& run);
// Title, environment, the table and notes on reading it.
std::string markdown_report(const RunRecord& run);
void write_markdown_report(const std::filesystem::path& path, const RunRecord& run);

}  // namespace canopy
