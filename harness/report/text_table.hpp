// Aligned Markdown tables, and the number formats every table of a run shares.
#pragma once

#include "metrics/metric_registry.hpp"
#include "run/block_bootstrap.hpp"
#include "run/case_result.hpp"

#include <string>
#include <vector>

namespace canopy {

// A Markdown table whose columns line up in plain text too.
std::string render_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                         const std::vector<bool>& right_aligned);

// 4 significant digits; "-" where a metric has nothing to measure (NaN), "inf" for identical images.
std::string metric_cell(double value);
// The same, or "n/a" where the technique does not declare the metric meaningful (ErrorColumns).
std::string metric_cell(double value, bool meaningful);
// A registered metric's cell: "n/a" outside the technique's declared groups, percent where it says so.
std::string table_cell(const MetricInfo& metric, const ImageMetrics& m);

// The registered metrics a table of `run` shows (`where`): none when no case measured errors, and
// of the others only those whose group some case declares (a grass run shows no shadow columns)
// and, for a metric `only_when_measured`, that some case measured.
std::vector<const MetricInfo*> shown_metrics(const RunRecord& run, MetricShown where);

// A time ratio and its 95 % interval, "1.93 [1.88, 1.99]"; "-" when not measured.
std::string ratio_cell(const Estimate& ratio);
// A time ratio: two decimals, or two significant figures below 0.1 (0.014, not 0.01).
std::string ratio_number(double ratio);

}  // namespace canopy
