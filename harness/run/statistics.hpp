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

}  // namespace canopy
