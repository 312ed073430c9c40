// `canopy report`: one run as one static HTML page that needs nothing else (no network, no
// external script): the environment, the sortable results table, the Pareto fronts (tables and
// charts), the paper comparison when the run reproduces a paper (its paper.md), and per case the
// technique's image, the reference, the error map and the FLIP map side by side, zoomed and panned
// together. The page checks itself when opened with #selftest (tests/report/).
#pragma once

#include "run/case_result.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

struct HtmlReportOptions {
    // Images as data: URIs inside the page (it can be moved and mailed); false: links relative to
    // the run folder (a smaller page, which must stay beside its images/).
    bool embed_images = true;
    // The Pareto fronts' error axes (results.json names, `canopy metrics`); empty: the ones the
    // run's technique families declare (Technique::pareto_errors).
    std::vector<std::string> pareto_metrics;
};

// `run` as read from `run_dir`/results.json; images and paper.md are read from `run_dir`.
std::string html_report(const RunRecord& run, const std::filesystem::path& run_dir, const HtmlReportOptions& options);

// Reads run_dir/results.json and writes the page to `out` atomically. Throws std::runtime_error
// naming what is missing.
void write_html_report(const std::filesystem::path& run_dir, const std::filesystem::path& out,
                       const HtmlReportOptions& options);

}  // namespace canopy
