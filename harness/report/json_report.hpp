// results.json: every case with every sample, its statistics, parameters and the environment.
#pragma once

#include "run/case_result.hpp"

#include <filesystem>
#include <string>

namespace canopy {

// 2: the run's identity (what a resumed run must match), resumed_at and the run's error.
// 3: technique-isolated visibility errors and the columns a technique declares meaningful; shadow
//    regions from the pixel-centre visibility; the references' pixel visibility; groups measured
//    round by round: per case its group, chunk, per-round ratio to the group's baseline with its
//    interval, CPU time and sample start times; samples are per round.
inline constexpr int kResultsVersion = 3;

std::string json_report(const RunRecord& run);
void write_json_report(const std::filesystem::path& path, const RunRecord& run);

}  // namespace canopy
