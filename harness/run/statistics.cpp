#include "run/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace canopy {

namespace {

double median_of_sorted(const std::vector<double>& v) {
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

double quantile_of_sorted(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double position = q * double(sorted.size() - 1);
    const size_t below = size_t(std::floor(position));
    const size_t above = std::min(below + 1, sorted.size() - 1);
    const double t = position - double(below);
    return sorted[below] + t * (sorted[above] - sorted[below]);
}

SampleStats summarize(std::vector<double> samples) {
    SampleStats s;
    s.count = samples.size();
    if (samples.empty()) return s;
    std::sort(samples.begin(), samples.end());
    s.min = samples.front();
    s.max = samples.back();
    s.median = median_of_sorted(samples);
    s.mean = std::accumulate(samples.begin(), samples.end(), 0.0) / double(s.count);
    std::vector<double> deviations;
    deviations.reserve(s.count);
    for (double x : samples) deviations.push_back(std::abs(x - s.median));
    std::sort(deviations.begin(), deviations.end());
    s.mad = median_of_sorted(deviations);
    if (s.count > 1 && s.mean != 0.0) {
        double squares = 0.0;
        for (double x : samples) squares += (x - s.mean) * (x - s.mean);
        s.cv = std::sqrt(squares / double(s.count - 1)) / s.mean;
    }
    return s;
}

}  // namespace canopy
