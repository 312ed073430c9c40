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

// `canopy run --runs N` keeps runs 2..N of the experiment in <run folder>/runs/run-<k>/.
inline constexpr int kMinRunsForOwnNoise = 5;
std::filesystem::path repeated_run_folder(const std::filesystem::path& run_dir, int k);

struct RunRecord;
// The spread between this experiment's own runs: `run` and the complete runs of the same experiment
// and config under run_dir/runs/, when there are at least kMinRunsForOwnNoise of them in all (the
// largest sigma over its cases); else the checkout's (checkout_run_to_run_noise). The source says
// which.
RunToRunNoise run_to_run_noise_for(const RunRecord& run, const std::filesystem::path& run_dir);

}  // namespace canopy
