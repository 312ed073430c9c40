// results.md: a readable, pasteable Markdown table per run with every column (the console gets the
// compact one, console_table.hpp).
#pragma once

#include "run/case_result.hpp"

#include <filesystem>
#include <string>

namespace canopy {

// The full table alone: timings, spread, passes, memory, every error column.
std::string markdown_table(const RunRecord& run);
// Title, environment, the table and notes on reading it.
std::string markdown_report(const RunRecord& run);
void write_markdown_report(const std::filesystem::path& path, const RunRecord& run);

}  // namespace canopy
