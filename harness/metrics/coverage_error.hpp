// How far a technique's population coverage is from the reference's: per pixel, the fraction of
// the pixel covered by the scene's populations (grass blades), the technique's read from its colour
// target's alpha (core/pixel_visibility.hpp kCoverage), the reference's counted over its pixel
// samples (ReferenceImages::visibility B). Three scales, so that a representation's own error is not
// lost in aliasing that every rasteriser shares: per pixel (aliasing included), over tiles of
// kCoverageTile x kCoverageTile pixels (a one-sample raster's coverage is an unbiased estimate of the
// true coverage, so its aliasing averages out over a tile while thinned, thickened or shifted grass
// does not), and over the whole image.
#pragma once

#include "core/image.hpp"

namespace canopy {

inline constexpr int kCoverageTile = 8;

struct CoverageError {
    // mean |c_t - c_r| over the covered pixels (c_t > 0 or c_r > 0)
    double mae;
    // mean over tiles with a covered pixel of |mean c_t - mean c_r|, the means over the tile's pixels
    // (edge tiles over the pixels they have)
    double tile_mae;
    // |sum c_t - sum c_r| / sum c_r: the share of the true coverage the technique gains or loses
    double total_error;
    // sum c_t / sum c_r - 1: its sign says thinned (< 0) or thickened (> 0)
    double bias;
    long long pixels;  // covered pixels; every metric is NaN when 0 (total_error and bias also when sum c_r = 0)
};

// Reads channel `kCoverage` (2, B) of both images. Pixels where either is non-finite take no part.
// Throws std::invalid_argument on mismatched or empty images.
CoverageError compute_coverage_error(const Image& technique, const Image& reference);

}  // namespace canopy
