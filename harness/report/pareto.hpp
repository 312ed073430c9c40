// Pareto fronts of a run: per group (one scene at one resolution, measured together), the
// configurations no other configuration beats in both time and one error metric.
//
// Time is each case's paired ratio to another case of its group (run/case_ratio.hpp: round by round
// where they share a chunk), with its 95 % interval; an error is deterministic, and a difference
// counts only beyond the metric's compare tolerance (metrics/metric_registry.hpp: what `canopy
// compare` lets a metric move between two runs). B dominates A when B is
//   - not significantly worse in error (B's error at most A's plus the tolerance, in the metric's
//     better direction),
//   - not significantly slower (the interval of time(B) / time(A) does not lie wholly above 1),
//   - and significantly better in one of them: its time ratio's interval lies wholly below 1, or
//     its error is better by more than the tolerance.
// So two configurations whose times are within noise of each other and whose errors are within
// tolerance both stay on the front: a configuration is dominated only by a difference that is
// significant. With fewer rounds than canopy compare judges (kMinComparedRounds; --quick measures
// 3), nothing is dominated. results.md's "dominated by" column is the first front's
// (default_pareto_metrics), so the two reports agree.
#pragma once

#include "run/case_result.hpp"

#include <string>
#include <vector>

namespace canopy {

struct ParetoPoint {
    const CaseResult* result = nullptr;
    Estimate time_ratio;        // GPU time / the group's baseline's, median and 95 % interval
    double error = 0;           // the metric's value (NaN: not measured, not on any front)
    bool dominated = false;
    std::string dominated_by;   // the id of one case that dominates it
};

struct ParetoFront {
    std::string group;          // "car 1920x1080"
    std::string metric;         // results.json name of the error axis
    std::vector<ParetoPoint> points;  // every case of the group that has a time and this metric, in run order
    std::vector<std::string> unmeasured;  // ids of ok cases without a time or this metric
    // Whether dominance was judged: at least two points measured kMinComparedRounds rounds. When
    // not (--quick), no point is dominated for want of time intervals, and none is a front either.
    bool judged = false;
};

// Whether `b` dominates `a` on `metric` (the rules above).
bool dominates(const ParetoPoint& b, const ParetoPoint& a, const std::string& metric);

// The front of every group of `run` on one error metric (a results.json name, `canopy metrics`).
// Throws std::invalid_argument for an unknown metric.
std::vector<ParetoFront> pareto_fronts(const RunRecord& run, const std::string& metric);

// Why no configuration of `run` is judged dominated when it measured fewer rounds than
// kMinComparedRounds (--quick); "" when it measured enough.
std::string too_few_rounds_note(const RunRecord& run);

// The error axes a run's fronts are drawn on by default: the axes the families of its techniques
// declare (Technique::pareto_errors), in order of first appearance; unknown techniques add none.
std::vector<std::string> default_pareto_metrics(const RunRecord& run);

}  // namespace canopy
