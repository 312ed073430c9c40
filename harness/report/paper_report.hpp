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

// A claim's outcome on canopy's numbers. Timing claims account for noise: a difference smaller
// than twice the summed MADs of the two medians decides nothing ("within noise").
struct ClaimVerdict {
    std::string text;
    std::string outcome = "not measured";  // holds | does not hold | within noise | not measured
    bool decided() const { return outcome == "holds" || outcome == "does not hold"; }
    bool holds() const { return outcome == "holds"; }
    std::string because;                   // the numbers behind the verdict
};

std::vector<ClaimVerdict> judge_claims(const PaperComparison& paper, const RunRecord& run);
std::string paper_report(const PaperComparison& paper, const RunRecord& run);
void write_paper_report(const std::filesystem::path& path, const PaperComparison& paper, const RunRecord& run);

}  // namespace canopy
