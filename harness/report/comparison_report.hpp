// The table `canopy compare` prints (and writes with --out): the two runs, what differs between
// them, per case the change of its time ratio with its interval and verdict, every error metric
// out of tolerance, the cases only one run has, and a summary that says what exit code follows.
#pragma once

#include "run/run_comparison.hpp"

#include <string>

namespace canopy {

struct ComparedRun {
    std::string path;  // as given on the command line
    const RunRecord* run = nullptr;
};

std::string comparison_report(const ComparedRun& baseline, const ComparedRun& candidate, const RunComparison& comparison);

}  // namespace canopy
