#include "run/case_ratio.hpp"

#include "run/group_measurement.hpp"

namespace canopy {

CaseRatio time_ratio(const CaseResult& a, const CaseResult& b) {
    const uint64_t seed = bootstrap_seed(a.id + "/" + b.id);
    const bool same_group = a.scene == b.scene && a.resolution.width == b.resolution.width &&
                            a.resolution.height == b.resolution.height && a.group == b.group;
    // Against its own group's baseline: the ratio it recorded (the same numbers as the ratio column).
    if (same_group && b.group_baseline && a.ratio.measured()) return {a.ratio.estimate, RatioPairing::rounds};
    if (same_group && a.chunk == b.chunk && a.ratio.measured() && a.ratio.per_round.size() == b.ratio.per_round.size()) {
        // Round by round, each through the baseline samples it was paired with.
        const RatioRecord paired = paired_ratio(a.ratio.per_round, b.ratio.per_round, a.id + "/" + b.id);
        return {paired.estimate, RatioPairing::rounds};
    }
    if (same_group && a.chunk == b.chunk && !a.gpu_frame.samples_ms.empty()) {
        const RatioRecord paired = paired_ratio(a.gpu_frame.samples_ms, b.gpu_frame.samples_ms, a.id + "/" + b.id);
        return {paired.estimate, RatioPairing::rounds};
    }
    if (same_group && a.ratio.measured() && b.ratio.measured())
        return {ratio_of_medians_with_ci(a.ratio.per_round, b.ratio.per_round, seed), RatioPairing::via_baseline};
    return {ratio_of_medians_with_ci(a.gpu_frame.samples_ms, b.gpu_frame.samples_ms, seed), RatioPairing::unpaired};
}

CaseRatio series_ratio(const CaseResult& a, const TimingSeries& a_series, const CaseResult& b,
                       const TimingSeries& b_series) {
    if (&a_series == &a.gpu_frame && &b_series == &b.gpu_frame) return time_ratio(a, b);
    const bool same_chunk = a.scene == b.scene && a.resolution.width == b.resolution.width &&
                            a.resolution.height == b.resolution.height && a.group == b.group && a.chunk == b.chunk;
    if (same_chunk && !a_series.samples_ms.empty() && a_series.samples_ms.size() == b_series.samples_ms.size())
        return {paired_ratio(a_series.samples_ms, b_series.samples_ms, a.id + "/" + a_series.name + "/" + b.id + "/" + b_series.name)
                    .estimate,
                RatioPairing::rounds};
    return {ratio_of_medians_with_ci(a_series.samples_ms, b_series.samples_ms,
                                     bootstrap_seed(a.id + "/" + a_series.name + "/" + b.id + "/" + b_series.name)),
            RatioPairing::unpaired};
}

}  // namespace canopy
