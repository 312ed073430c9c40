// paper.md: a paper's table and canopy's measurements side by side, times normalised to the
// paper's baseline row (the paper's GPU and this device differ, so ratios are what compare),
// canopy's error columns, and a verdict per claim.
#pragma once

#include "config/paper_comparison.hpp"
#include "run/case_result.hpp"
#include "run/run_to_run_noise.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

// Fewer measured rounds than this decide no timing claim. Below 6 samples even a sample's whole
// range [min, max] is not a 95 % confidence interval of the median (it covers it with probability
// 1 - 2 * 0.5^n: 75 % for the 3 rounds of --quick, 94 % for 5, 97 % for 6; distribution-free), so
// no bootstrap interval made from them bounds where the median lies.
inline constexpr size_t kMinTimingSamples = 6;

// A claim's outcome on canopy's numbers. Timing claims account for noise: a time ratio whose 95 %
// interval (run/case_ratio.hpp, widened by the run-to-run spread) reaches across the claim's
// boundary decides nothing ("within noise"), nor do timings of fewer than kMinTimingSamples rounds
// ("too few samples").
struct ClaimVerdict {
    std::string text;
    // The direction (the relation): holds | does not hold | within noise | too few samples |
    // not measured | not tested by canopy | not judged: flagged case (every case it compares was
    // measured against a degenerate reference, metrics/reference_degeneracy.hpp)
    std::string outcome = "not measured";
    bool decided() const { return outcome == "holds" || outcome == "does not hold"; }
    bool holds() const { return outcome == "holds"; }
    std::string because;                   // the numbers behind the verdict
    // states = direction: why it checks no number (config/claim_rules.hpp's reason, in words).
    std::string direction_only;
    // states = magnitude: canopy's ratio as × k of the paper's, and its verdict (the outcomes
    // above, or "not judged on a CPU rasteriser" for times measured on lavapipe).
    bool magnitude_stated = false;
    std::string magnitude_outcome;
    std::string magnitude;
    // A speed claim whose rows differ in error beyond the metric's compare tolerance: "unequal
    // quality: FLIP 0.21 vs 0.09; ..."; "" otherwise.
    std::string unequal_quality;
};

// A ratio's interval widened by the spread between runs, on the log-ratio: each side
// √(side² + (1.96 σ)²), i.e. ±1.96 √(se_within² + σ_run²) for a symmetric interval.
Estimate with_run_to_run_noise(const Estimate& ratio, double sigma);

std::vector<ClaimVerdict> judge_claims(const PaperComparison& paper, const RunRecord& run, const RunToRunNoise& noise);
std::string paper_report(const PaperComparison& paper, const RunRecord& run, const RunToRunNoise& noise);
void write_paper_report(const std::filesystem::path& path, const PaperComparison& paper, const RunRecord& run,
                        const RunToRunNoise& noise);

// paper.json beside paper.md: the same numbers as data, for plots (scripts/plot-paper) — per row
// and column the paper's value and time ratio, canopy's time ratio with its interval (widened by
// the run-to-run noise), its median time, the case id and every registered error metric (null
// where not measured); the claims' verdicts; the run-to-run noise and where it comes from; the
// run's commit, device, driver and whole environment, as its results.json has them.
nlohmann::json paper_data(const PaperComparison& paper, const RunRecord& run, const RunToRunNoise& noise);
void write_paper_data(const std::filesystem::path& path, const PaperComparison& paper, const RunRecord& run,
                      const RunToRunNoise& noise);

}  // namespace canopy
