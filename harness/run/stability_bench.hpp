// `canopy bench stability EXPERIMENT --runs N`: a benchmark of the instrument itself. It runs the
// experiment N times, each a separate `canopy run` process (no reference, no images), exactly as a
// user would, and reports per case how still its readings hold:
//   within-run CV     the coefficient of variation of the case's samples within one run (median
//                     over the runs; the worst run too);
//   run-to-run spread of the case's ratio to its group's baseline: (max - min) / median over the
//                     runs, and the standard deviation over the runs relative to their mean.
// Targets (issue 8, on a shared 2-core machine): spread <= 5 % for cases over 20 ms, CV <= 5 %.
#pragma once

#include "run/case_result.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

inline constexpr double kTargetRatioSpread = 0.05;
inline constexpr double kTargetWithinRunCv = 0.05;
inline constexpr double kTargetSpreadAboveMs = 20.0;  // the spread target applies to cases slower than this

struct CaseStability {
    std::string id;
    std::string label;           // "spheres 640x360 shadow.pcf kernel=5"
    bool group_baseline = false;
    double median_ms = 0;        // median over runs of the case's median GPU time
    std::vector<double> ratios;  // per run: the median of its per-round ratios
    std::vector<double> cvs;     // per run: within-run CV of its GPU samples
    double ratio_median = 0;
    double ratio_spread = 0;     // (max - min) / median of `ratios`
    double ratio_cv = 0;         // sample std / mean of `ratios`
    double within_cv_median = 0, within_cv_max = 0;
    // The same ratio from the process's CPU time instead of GPU timestamps (on lavapipe the
    // timestamps also count the time the rasterising thread waited for a CPU; CPU time does not).
    std::vector<double> cpu_ratios;
    double cpu_ratio_spread = 0;
    bool spread_target_applies() const { return !group_baseline && median_ms > kTargetSpreadAboveMs; }
    bool meets_spread_target() const { return ratio_spread <= kTargetRatioSpread; }
    bool meets_cv_target() const { return within_cv_median <= kTargetWithinRunCv; }
};

// One run of the benchmark, as it happened.
struct StabilityRun {
    std::filesystem::path folder;  // its run folder
    std::array<double, 3> load_before{}, load_after{};
    double seconds = 0;
};

struct StabilityResult {
    std::string experiment, config_file;
    Environment environment;  // of the first run
    int warmup_frames = 0, rounds = 0, frames_per_sample = 0;
    std::vector<StabilityRun> runs;
    std::vector<CaseStability> cases;  // in the experiment's order
};

// The statistics of N recorded runs of one experiment. Throws std::runtime_error when the runs
// are not of one experiment and config.
StabilityResult analyse_stability(const std::vector<RunRecord>& runs);

// Runs `argv` (argv[0] an executable's path) with stdout and stderr into `log`; returns its exit
// status (128 + signal if killed).
int run_process(const std::vector<std::string>& argv, const std::filesystem::path& log);

struct StabilityOptions {
    std::filesystem::path experiment;
    int runs = 5;
    std::filesystem::path out;  // the report's folder; each run's folder is under runs/
    bool quick = false;         // pass --quick to the runs (smoke tests)
    std::string device;
};

// Runs `canopy run` (the executable `canopy`) N times into options.out/runs/run-<k>/ and analyses
// them. Throws std::runtime_error when a run fails (its log is named).
StabilityResult run_stability_bench(const std::filesystem::path& canopy, const StabilityOptions& options);

// Analyses run folders made earlier (e.g. by scripts/measurement-study, which interleaves the
// runs of several settings so the machine's load falls on all alike). The load before each run
// is the one its results.json recorded at its start; after it, unknown (NaN).
StabilityResult analyse_run_folders(const std::vector<std::filesystem::path>& folders);

}  // namespace canopy
