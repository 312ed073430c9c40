// The reference's own noise, carried into every metric (issue 35). The reference is a Monte Carlo
// estimate whose per-pixel variance it records; a metric against it moves with that noise, and two
// techniques' errors differ by less than it decides nothing. canopy measures how far: each case's
// metrics are computed again against kReferenceReplicates copies of the reference perturbed by its
// own noise (a parametric bootstrap over its samples), the same copies for every case of one
// reference, so the gap between two cases' errors is measured replicate by replicate.
#pragma once

#include "core/image.hpp"

#include <vector>

namespace canopy {

inline constexpr int kReferenceReplicates = 8;

// radiance + sqrt(variance) x z per pixel and channel, z standard normal from (replicate, pixel,
// channel) alone: the same for every case and every machine. Alpha is kept. The recorded variance
// is conservative for stratified sampling (reference_renderer.hpp), so the spread is too.
Image perturbed_reference(const Image& radiance, const Image& variance, int replicate);

// The sample standard deviation of the finite values; NaN for fewer than two.
double replicate_spread(const std::vector<double>& values);

}  // namespace canopy
