// results.gbench.json: a run's timings in Google Benchmark's JSON output format (a file format
// only, no Google code), so tools written for it (compare.py, dashboards) can read canopy's runs.
//
// Each case is one benchmark, "<case id>/manual_time" (Google Benchmark's suffix for a benchmark
// whose real_time is measured by the benchmark itself, as GPU times are): one "iteration" entry
// per measured round (repetitions = rounds, iterations = frames per sample), real_time = the
// sample's GPU time per frame, cpu_time = the process's CPU time per frame, time_unit "ms";
// counters: wall_ms, ratio (to the group's baseline, same round), <pass>_ms per pass and the
// technique's counts as counter_<name> (CaseResult::counters, one frame's, alike in every round). Then the
// aggregates Google Benchmark writes for repeated runs: _mean, _median, _stddev and _cv (cv as a
// fraction, aggregate_unit "percentage"). A failed case is one entry with error_occurred.
#pragma once

#include "run/case_result.hpp"

#include <filesystem>
#include <string>

namespace canopy {

std::string gbench_report(const RunRecord& run);
void write_gbench_report(const std::filesystem::path& path, const RunRecord& run);

}  // namespace canopy
