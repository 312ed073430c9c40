// paper.md: a paper's table and canopy's measurements side by side, times normalised to the
// paper's baseline row (the paper's GPU and this device differ, so ratios are what compare),
// canopy's error columns, and a verdict per claim.
#pragma once

#include "config/paper_comparison.hpp"
#include "run/case_result.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

struct ClaimVerdict {
    std::string text;
    bool decided = false;  // false when a row has no measured case
    bool holds = false;
    std::string because;   // the numbers behind the verdict
};

std::vector<ClaimVerdict> judge_claims(const PaperComparison& paper, const RunRecord& run);
std::string paper_report(const PaperComparison& paper, const RunRecord& run);
void write_paper_report(const std::filesystem::path& path, const PaperComparison& paper, const RunRecord& run);

}  // namespace canopy
