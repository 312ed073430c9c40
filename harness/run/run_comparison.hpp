// `canopy compare BASELINE CANDIDATE`: has anything changed between two runs of one experiment —
// typically two commits, or two devices? Per case (matched by id):
//   time:   the relative change of the case's time ratio to its group's baseline, from each run's
//           per-round ratios, with a 95 % interval from resampling each run's rounds on its own
//           (circular block bootstrap). A regression is flagged only when the whole interval lies
//           above the threshold (an improvement: below minus the threshold). Ratios, not absolute
//           times: on a shared machine the load moves absolute times between runs, while a ratio
//           measured round by round keeps still. The group's baseline case itself has ratio 1;
//           its absolute time change is shown, never flagged.
//   errors: every registered error metric against its tolerance, |candidate - baseline| <=
//           absolute + relative x |baseline| (metrics/metric_registry.cpp: rendering rounds
//           differently on another CPU or device moves errors a little, never by more).
// Runs of different experiments or configs are refused; different commits, devices, builds and
// run options are allowed (that is the point) and named in the report.
#pragma once

#include "run/case_result.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace canopy {

// Two runs that do not measure the same thing (another experiment, another config).
class ComparisonRefused : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Fewer rounds than this judge no time change (as paper claims, report/paper_report.hpp): the
// block bootstrap of 3 rounds (--quick) has almost nothing to resample.
inline constexpr size_t kMinComparedRounds = 6;

struct ComparisonSettings {
    double threshold = 0.05;  // a change of a time ratio smaller than this is not a regression
    bool time = true;         // compare time ratios
    bool errors = true;       // compare error metrics
};

enum class TimeVerdict {
    unchanged,      // the interval lies within +-threshold
    inconclusive,   // the interval reaches past +-threshold but not wholly: not flagged
    regression,     // the interval lies above +threshold: flagged
    improvement,    // the interval lies below -threshold
    baseline,       // the group's baseline: its ratio is 1 by definition
    too_few_rounds, // fewer than kMinComparedRounds on one side: no interval to judge by
    not_compared,   // failed or not timed on one side
};
const char* to_string(TimeVerdict verdict);

struct TimeChange {
    TimeVerdict verdict = TimeVerdict::not_compared;
    Estimate baseline_ratio, candidate_ratio;  // each run's median ratio and its interval
    Estimate change;                           // candidate / baseline - 1 of the ratios (for the group's baseline: of its GPU time)
};

struct MetricChange {
    std::string metric;  // as in results.json's image_error
    double baseline = 0, candidate = 0;
    double allowed = 0;  // the tolerance for this baseline value
    bool out_of_tolerance = false;
};

struct CaseComparison {
    std::string id;
    std::string label;  // "spheres 640x360 shadow.pcf kernel=5"
    bool failed_baseline = false, failed_candidate = false;
    TimeChange time;
    std::vector<MetricChange> errors;  // every metric compared (both runs have errors)
    bool errors_out_of_tolerance() const;
};

struct RunComparison {
    std::vector<CaseComparison> cases;  // in the baseline's order, then the candidate's
    std::vector<std::string> only_in_baseline, only_in_candidate;  // case ids
    std::vector<std::string> differences;  // "commit: abc1234 -> def5678", what differs between the runs
    ComparisonSettings settings;

    size_t regressions() const;
    size_t improvements() const;
    size_t errors_out_of_tolerance() const;  // cases with a metric out of tolerance
    size_t newly_failed() const;             // cases that failed in the candidate only
    bool passed() const;                     // nothing flagged (exit code 0)
};

// Throws ComparisonRefused when the two runs are of different experiments or configs.
RunComparison compare_runs(const RunRecord& baseline, const RunRecord& candidate, const ComparisonSettings& settings);

}  // namespace canopy
