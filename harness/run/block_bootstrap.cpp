#include "run/block_bootstrap.hpp"

#include "run/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace canopy {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Interval percentile_interval(std::vector<double> replicates) {
    std::sort(replicates.begin(), replicates.end());
    const double tail = 0.5 * (1.0 - kConfidence);
    return {quantile_of_sorted(replicates, tail), quantile_of_sorted(replicates, 1.0 - tail)};
}

// A statistic of two independently resampled series, with its interval.
template <class Statistic>
Estimate two_series(const std::vector<double>& a, const std::vector<double>& b, uint64_t seed, Statistic statistic) {
    Estimate e;
    e.count = std::min(a.size(), b.size());
    if (a.empty() || b.empty()) return {kNaN, {kNaN, kNaN}, 0};
    e.value = statistic(median_of(a), median_of(b));
    if (a.size() == 1 && b.size() == 1) {
        e.ci = {e.value, e.value};
        return e;
    }
    SplitMix64 random(seed);
    const size_t la = default_block_length(a.size()), lb = default_block_length(b.size());
    std::vector<double> ra, rb, replicates;
    replicates.reserve(kBootstrapResamples);
    for (int i = 0; i < kBootstrapResamples; ++i) {
        resample_blocks(a, la, random, ra);
        resample_blocks(b, lb, random, rb);
        replicates.push_back(statistic(median_of(ra), median_of(rb)));
    }
    e.ci = percentile_interval(std::move(replicates));
    return e;
}

}  // namespace

size_t default_block_length(size_t n) {
    if (n <= 1) return 1;
    const size_t length = size_t(std::ceil(std::cbrt(double(n)) - 1e-9));
    return std::clamp<size_t>(length, 1, n);
}

uint64_t SplitMix64::next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

size_t SplitMix64::below(size_t n) {
    // Lemire's multiply-shift on the top 32 bits: bias below 2^-32 * n, irrelevant here.
    return size_t(((next() >> 32) * uint64_t(n)) >> 32);
}

uint64_t bootstrap_seed(std::string_view label) {
    uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a
    for (unsigned char c : label) hash = (hash ^ c) * 0x100000001b3ull;
    return hash ^ 0x63616e6f70790001ull;  // "canopy", version 1 of the resampling scheme
}

void resample_blocks(const std::vector<double>& values, size_t block_length, SplitMix64& random, std::vector<double>& out) {
    const size_t n = values.size();
    out.clear();
    out.reserve(n);
    while (out.size() < n) {
        const size_t start = random.below(n);
        for (size_t j = 0; j < block_length && out.size() < n; ++j) out.push_back(values[(start + j) % n]);
    }
}

double median_of(std::vector<double> values) {
    if (values.empty()) return kNaN;
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(mid), values.end());
    const double upper = values[mid];
    if (values.size() % 2) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(mid));
    return 0.5 * (lower + upper);
}

Estimate median_with_ci(const std::vector<double>& values, uint64_t seed) {
    Estimate e;
    e.count = values.size();
    if (values.empty()) return {kNaN, {kNaN, kNaN}, 0};
    e.value = median_of(values);
    if (values.size() == 1) {
        e.ci = {e.value, e.value};
        return e;
    }
    SplitMix64 random(seed);
    const size_t length = default_block_length(values.size());
    std::vector<double> resample, replicates;
    replicates.reserve(kBootstrapResamples);
    for (int i = 0; i < kBootstrapResamples; ++i) {
        resample_blocks(values, length, random, resample);
        replicates.push_back(median_of(resample));
    }
    e.ci = percentile_interval(std::move(replicates));
    return e;
}

Estimate relative_change_with_ci(const std::vector<double>& denominator, const std::vector<double>& numerator,
                                       uint64_t seed) {
    return two_series(numerator, denominator, seed, [](double n, double d) { return n / d - 1.0; });
}

Estimate ratio_of_medians_with_ci(const std::vector<double>& numerator, const std::vector<double>& denominator,
                                        uint64_t seed) {
    return two_series(numerator, denominator, seed, [](double n, double d) { return n / d; });
}

}  // namespace canopy
