// Confidence intervals for medians of timing series whose noise comes in runs: a load change on a
// shared machine lasts several measured rounds, so rounds are not independent. The circular block
// bootstrap resamples blocks of consecutive rounds (wrapping around the end), which keeps that
// dependence inside each block (Politis & Romano 1992). Every resample comes from a fixed seed, so
// the same samples always give the same interval.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace canopy {

struct Interval {
    double low = 0, high = 0;
};

// A statistic (a median, a ratio of medians, a relative change) with its two-sided 95 %
// percentile-bootstrap interval.
struct Estimate {
    double value = 0;
    Interval ci;
    size_t count = 0;  // values it was computed from
};

inline constexpr int kBootstrapResamples = 2000;
inline constexpr double kConfidence = 0.95;

// Block length for n rounds: ceil(n^(1/3)) (the order Hall, Horowitz and Jing 1995 find best for
// variance and bias), clamped to [1, n]. 30 rounds -> 4, 10 -> 3, 3 -> 2.
size_t default_block_length(size_t n);

// Deterministic pseudo-random numbers (splitmix64), the same on every platform and standard
// library, unlike std::uniform_int_distribution.
class SplitMix64 {
public:
    explicit SplitMix64(uint64_t seed) : state_(seed) {}
    uint64_t next();
    size_t below(size_t n);  // uniform in [0, n), n >= 1

private:
    uint64_t state_;
};

// The seed for a series named `label` (a case id): the same label always resamples the same way.
uint64_t bootstrap_seed(std::string_view label);

// One circular-block resample of `values` (same length) into `out`.
void resample_blocks(const std::vector<double>& values, size_t block_length, SplitMix64& random, std::vector<double>& out);

double median_of(std::vector<double> values);  // NaN when empty

// Median of `values` with a 95 % circular-block-bootstrap interval. One value: the interval is
// that value; none: NaN everywhere.
Estimate median_with_ci(const std::vector<double>& values, uint64_t seed);

// median(numerator) / median(denominator) - 1, with a 95 % interval from resampling the two
// series independently (block bootstrap each): how much larger the first series' median is.
// For two runs' per-round ratios of one case, the relative change of its ratio.
Estimate relative_change_with_ci(const std::vector<double>& denominator, const std::vector<double>& numerator,
                                       uint64_t seed);

// median(numerator) / median(denominator), with the same independent resampling: the ratio of two
// series that were not measured in the same rounds.
Estimate ratio_of_medians_with_ci(const std::vector<double>& numerator, const std::vector<double>& denominator,
                                        uint64_t seed);

}  // namespace canopy
