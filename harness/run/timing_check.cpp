#include "run/timing_check.hpp"

#include "run/statistics.hpp"

#include <algorithm>

namespace canopy {

TimingCheck check_pass_timing(const std::vector<std::vector<double>>& passes, const std::vector<double>& wall) {
    TimingCheck check;
    if (passes.empty() || wall.empty()) return check;
    size_t rounds = wall.size();
    for (const auto& p : passes) rounds = std::min(rounds, p.size());
    if (rounds == 0) return check;
    std::vector<double> sums(rounds, 0.0), gaps(rounds);
    for (const auto& p : passes)
        for (size_t r = 0; r < rounds; ++r) sums[r] += p[r];
    for (size_t r = 0; r < rounds; ++r) gaps[r] = wall[r] - sums[r];
    check.checked = true;
    check.pass_sum_ms = summarize(sums).median;
    check.wall_ms = summarize(std::vector<double>(wall.begin(), wall.begin() + long(rounds))).median;
    check.gap_ms = summarize(gaps).median;
    check.tolerance_ms = std::max(kTimingCheckRelative * check.wall_ms, kTimingCheckAbsoluteMs);
    return check;
}

}  // namespace canopy
