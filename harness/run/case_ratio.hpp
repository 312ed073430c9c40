// How much longer one case takes than another, with a 95 % interval, using the best pairing the
// way they were measured allows:
//   - same group and chunk: paired round by round (each round's samples divided, then the median);
//   - same group, other chunks: each one's per-round ratios to the group's baseline, resampled
//     independently (the baseline divides out the load of each chunk);
//   - otherwise (another scene or resolution): their GPU samples, resampled independently — load
//     changes between the two are not cancelled.
#pragma once

#include "run/case_result.hpp"

namespace canopy {

enum class RatioPairing { rounds, via_baseline, unpaired };

struct CaseRatio {
    Estimate estimate;  // time of `a` / time of `b`
    RatioPairing pairing = RatioPairing::unpaired;
};

CaseRatio time_ratio(const CaseResult& a, const CaseResult& b);

// The same for two of their series (a pass's, or the frame's: one of the cases' TimingSeries),
// e.g. a pass of a case against its own frame: paired round by round within one group and chunk
// (the rounds line up), otherwise not.
CaseRatio series_ratio(const CaseResult& a, const TimingSeries& a_series, const CaseResult& b,
                       const TimingSeries& b_series);

}  // namespace canopy
