// Summary statistics of timing samples.
#pragma once

#include <cstddef>
#include <vector>

namespace canopy {

struct SampleStats {
    size_t count = 0;
    double median = 0, min = 0, max = 0, mean = 0;
    double mad = 0;  // median absolute deviation from the median (unscaled)
    double cv = 0;   // coefficient of variation: sample standard deviation / mean (0 if mean is 0)
};

SampleStats summarize(std::vector<double> samples);

// The q-quantile (q in [0, 1]) of values sorted ascending: linear interpolation between order
// statistics (type 7, as numpy and R's default); NaN for no values.
double quantile_of_sorted(const std::vector<double>& sorted, double q);

}  // namespace canopy
