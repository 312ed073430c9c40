// LDR-FLIP: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild,
// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020.
#pragma once

#include "core/image.hpp"

#include <vector>

namespace canopy {

// FLIP's default: 0.7 m from a 0.7 m wide 3840-pixel monitor, 0.7 * 3840 / 0.7 * pi / 180 = 67.02.
constexpr double default_flip_pixels_per_degree = 67.0;

// Per-pixel LDR-FLIP error in [0, 1], width * height floats, row-major, top row first.
//
// Follows the paper and NVIDIA's reference implementation (github.com/NVlabs/flip, FLIP.h):
//  1. Inputs are linear RGB; each channel is clamped to [0, 1]. (LDR-FLIP is defined on sRGB display
//     values, which FLIP decodes to linear RGB before anything else; for linear input the sRGB
//     encode/decode round trip is the identity, so only the clamp remains.)
//  2. linear RGB -> XYZ (D65) -> YyCxCz opponent space (the linearised L*a*b*).
//  3. Spatial CSF filtering per channel with the paper's Gaussians, sampled at 1/ppd degrees:
//     achromatic a1 = 1, b1 = 0.0047; red-green a1 = 1, b1 = 0.0053; blue-yellow a1 = 34.1,
//     b1 = 0.04, a2 = 13.5, b2 = 0.025; radius ceil(3 sqrt(0.04 / (2 pi^2)) ppd); each normalised to
//     sum 1; applied separably with clamp-to-edge borders, as in the reference code.
//  4. Filtered YyCxCz -> linear RGB, clamped to [0, 1] -> CIE L*a*b* -> Hunt adjustment
//     (a, b scaled by 0.01 L) -> HyAB distance, raised to q_c = 0.7, and mapped to [0, 1] with
//     p_c = 0.4, p_t = 0.95 against the largest distance (green vs blue).
//  5. Features on the unfiltered achromatic channel (Y + 16) / 116: first (edges) and second (points)
//     derivatives of a Gaussian, sigma = 0.5 * 0.082 * ppd, radius ceil(3 sigma), positive and
//     negative weights normalised to +1 / -1; feature difference
//     (max(|edge_ref - edge_test|, |point_ref - point_test|) / sqrt(2)) ^ q_f, q_f = 0.5.
//  6. FLIP = colour_difference ^ (1 - feature_difference).
// Pixels where either image has a non-finite channel are made equal to the reference before
// filtering (comparable_pair.hpp) and are NaN in the returned map. Throws std::invalid_argument on
// mismatched sizes or pixels_per_degree <= 0.
std::vector<float> compute_flip_map(const Image& test, const Image& reference,
                                    double pixels_per_degree = default_flip_pixels_per_degree);

struct FlipPooled {
    double mean = 0.0;
    // FLIP tool's "weighted median" (FLIPPooling::getPercentile(0.5, weighted = true)): sort the
    // values ascending and return the first value at which the running sum exceeds half of the
    // total sum, i.e. the median when every pixel is weighted by its own error. 0 when all errors are 0.
    double weighted_median = 0.0;
    long long pooled_pixels = 0;
};

// Pools the finite entries of a FLIP map (NaN entries, i.e. excluded pixels, are skipped).
// Both values are NaN when there is no finite entry.
FlipPooled pool_flip_map(const std::vector<float>& flip_map);

}  // namespace canopy
