// Whether a case's GPU pass times account for its frame (issue 9, item 8): per round, the sum of
// its GPU passes' timestamps is set beside the fence-to-fence wall time of the same sample, and
// the median of the paired differences must lie within max(10 % of the wall time, 0.5 ms).
// A timestamp that reads too short (a lone dispatch on lavapipe read 20-300x short in a
// standalone program) or too long shows as a gap; the case is flagged in the results.
#pragma once

#include <vector>

namespace canopy {

inline constexpr double kTimingCheckRelative = 0.10;
inline constexpr double kTimingCheckAbsoluteMs = 0.5;

struct TimingCheck {
    bool checked = false;     // false: no GPU pass, or no sample
    double pass_sum_ms = 0;   // median over the rounds of the sum of the GPU pass times
    double wall_ms = 0;       // median wall time, submit to fence
    double gap_ms = 0;        // median over the rounds of (wall - pass sum), paired
    double tolerance_ms = 0;  // max(kTimingCheckRelative x wall_ms, kTimingCheckAbsoluteMs)
    bool agrees() const { return !checked || (gap_ms <= tolerance_ms && gap_ms >= -tolerance_ms); }
};

// `passes[p][r]`: GPU pass p's time in round r; `wall[r]`: the same round's wall time.
TimingCheck check_pass_timing(const std::vector<std::vector<double>>& passes, const std::vector<double>& wall);

}  // namespace canopy
