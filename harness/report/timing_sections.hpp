// The Markdown sections of results.md that say how far a run's times can be trusted and where the
// CPU time goes: the timing cross-check (run/timing_check.hpp), the CPU side of every frame
// (recording, CPU passes) and, with a camera path, each pass's time over the frames of the path.
#pragma once

#include "run/case_result.hpp"

#include <string>
#include <vector>

namespace canopy {

std::string timing_check_section(const RunRecord& run);
std::string cpu_time_section(const RunRecord& run);
std::string camera_path_section(const RunRecord& run);

// One line per case whose GPU passes do not add up to its wall time, for the console.
std::vector<std::string> timing_check_warnings(const RunRecord& run);

}  // namespace canopy
