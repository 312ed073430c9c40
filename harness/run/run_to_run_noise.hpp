// The part of a time ratio's noise one run cannot see: how far it moves between process restarts
// (a new heap, new thread placement, another moment's load). `canopy bench stability` measures it;
// a claim's interval adds it to the run's own (report/paper_report.hpp), so a margin smaller than
// the spread between runs reads "within noise".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

struct RunToRunNoise {
    // Standard deviation of ln(ratio) between separate runs: 0.016 is a 1.6 % spread.
    double sigma = 0;
    // Where it comes from, for paper.md and paper.json: "results/stability/stability.json (llvmpipe
    // ..., 5 runs, largest of 4 cases)"; "" = not known.
    std::string source;
    bool known() const { return !source.empty(); }
};

// The standard deviation of ln(r) over one case's per-run ratios (0 for fewer than 2).
double log_ratio_sigma(const std::vector<double>& ratio_per_run);

// The largest run-to-run sigma among the cases of every stability.json under `folders` (searched
// recursively) measured on `device`; when none was measured on it, the largest over every device,
// and the source says so. Unknown (sigma 0, empty source) when there is no stability.json at all.
RunToRunNoise run_to_run_noise(const std::vector<std::filesystem::path>& folders, const std::string& device);

// The folders a checkout keeps stability measurements in: results/stability and
// results/gpu/<device>/stability.
std::vector<std::filesystem::path> stability_folders(const std::filesystem::path& checkout);

// run_to_run_noise over the stability folders of the checkout canopy runs from.
RunToRunNoise checkout_run_to_run_noise(const std::string& device);

}  // namespace canopy
