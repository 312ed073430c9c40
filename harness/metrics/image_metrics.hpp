// Every image-error metric of a test image against the ray-traced reference, in one call.
#pragma once

#include "core/error_columns.hpp"
#include "core/image.hpp"
#include "metrics/distance_bands.hpp"
#include "metrics/flip.hpp"
#include "metrics/pixel_classes.hpp"

#include <string>
#include <vector>

namespace canopy {

// Non-finite pixels: `nonfinite_pixels` counts TEST pixels with a NaN/Inf in any channel (RGBA).
// All other metrics are computed over the finite pixels only: a pixel where the test or the
// reference has a non-finite channel is excluded from every mean (see comparable_pair.hpp); a metric
// with nothing left to average is NaN.
struct ImageMetrics {
    // Linear RGB (alpha ignored), over the R, G, B values of all included pixels (pixel_error.hpp).
    // psnr = 20 log10(1 / rmse), peak 1.0, +infinity for identical images.
    double mae, rmse, psnr;
    double max_error;  // largest |test - ref| of any R, G, B value
    int max_x, max_y;  // where (first in row-major order on ties)

    double ssim;  // mean SSIM of clamped linear luminance, 11x11 Gaussian sigma 1.5, valid region (ssim.hpp)

    // LDR-FLIP (flip.hpp): mean of the per-pixel map, and the FLIP tool's weighted median.
    double flip_mean, flip_median_weighted;

    long long nonfinite_pixels;

    // FLIP's mean over the pixels of each distance band (distance_bands.hpp), when the experiment
    // sets [reference] distance_bands; NaN (and counts 0) otherwise or for an empty band.
    double flip_near, flip_middle, flip_far;
    long long near_pixels, middle_pixels, far_pixels;

    // Shadow-region metrics (shadow_error.hpp) over the reference's pixel-centre umbra, lit and
    // penumbra pixels off silhouettes (pixel_classes.hpp); NaN (and counts 0) when not computed
    // or the class is empty.
    double light_bleeding;
    double over_darkening;
    double penumbra_rmse;
    long long umbra_pixels, lit_pixels, penumbra_pixels;

    // Technique-isolated (visibility_error.hpp): the technique's visibility against the
    // reference's at the same pixel centres; NaN (and counts 0) when not computed or empty.
    double visibility_mae, visibility_rmse, visibility_penumbra_rmse;
    long long visibility_pixels, visibility_penumbra_pixels;
    double visibility_excluded;  // fraction of the pixels the light reaches left out (pixel_classes.hpp)

    // Population coverage (coverage_error.hpp): the technique's against the reference's, per
    // pixel, per 8x8 tile and over the image; NaN (and count 0) when not computed or nothing is covered.
    double coverage_mae, coverage_tile_mae, coverage_total_error;
    long long coverage_pixels;

    // Popping along the camera path (popping.hpp), set by the runner from one more traversal when
    // [camera_path] popping = true; NaN otherwise (compute_metrics leaves it so).
    double popping_mean, popping_max;

    // The groups above that mean something for the technique (its family's declaration); a report
    // shows the others as "n/a". They are NaN.
    ErrorColumns columns;
};

struct MetricOptions {
    double flip_pixels_per_degree = default_flip_pixels_per_degree;
    double visibility_epsilon = 1e-3;
    PixelClassOptions pixel_classes;
    // Each pixel's distance band (classify_distances), or null: no per-band metrics.
    const std::vector<DistanceBand>* distance_bands = nullptr;
};

// The technique's and the reference's pixel-centre visibility (core/pixel_visibility.hpp).
struct PixelVisibilityPair {
    const Image& technique;
    const Image& reference;
};

// Population coverage (core/pixel_visibility.hpp kCoverage, channel B of each): the technique's
// pixel-visibility image and the reference's ReferenceImages::visibility.
struct CoveragePair {
    const Image& technique;
    const Image& reference;
};

// `visibility` may be null: no shadow-region or visibility metrics; `coverage` may be null: no
// coverage metrics. `columns`: which of those the technique declares meaningful; only those are
// computed. When flip_map_out is given it receives
// the per-pixel FLIP map (for flip_heatmap) so it need not be computed twice.
// Throws std::invalid_argument on mismatched or empty images.
ImageMetrics compute_metrics(const Image& test, const Image& reference, const PixelVisibilityPair* visibility,
                             const CoveragePair* coverage, ErrorColumns columns, const MetricOptions& options = {},
                             std::vector<float>* flip_map_out = nullptr);

// A metric value for reports: "inf", "-inf", "nan", or up to 6 significant digits.
std::string format_metric_value(double value);

}  // namespace canopy
