#include "metrics/image_metrics.hpp"

#include "metrics/comparable_pair.hpp"
#include "metrics/coverage_error.hpp"
#include "metrics/pixel_error.hpp"
#include "metrics/shadow_error.hpp"
#include "metrics/ssim.hpp"
#include "metrics/visibility_error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace canopy {

ImageMetrics compute_metrics(const Image& test, const Image& reference, const PixelVisibilityPair* visibility,
                             const CoveragePair* coverage, ErrorColumns columns, const MetricOptions& options, std::vector<float>* flip_map_out) {
    require_same_size(test, reference, "compute_metrics");

    ImageMetrics metrics{};
    const PixelError pixel_error = compute_pixel_error(test, reference);
    metrics.mae = pixel_error.mae;
    metrics.rmse = pixel_error.rmse;
    metrics.psnr = pixel_error.psnr;
    metrics.max_error = pixel_error.max_error;
    metrics.max_x = pixel_error.max_x;
    metrics.max_y = pixel_error.max_y;

    metrics.ssim = compute_ssim(test, reference);

    std::vector<float> flip_map = compute_flip_map(test, reference, options.flip_pixels_per_degree);
    const FlipPooled flip = pool_flip_map(flip_map);
    metrics.flip_mean = flip.mean;
    metrics.flip_median_weighted = flip.weighted_median;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    metrics.flip_near = metrics.flip_middle = metrics.flip_far = nan;
    metrics.near_pixels = metrics.middle_pixels = metrics.far_pixels = 0;
    if (options.distance_bands) {
        const BandMeans by_band = band_means(flip_map, *options.distance_bands);
        metrics.flip_near = by_band.near;
        metrics.flip_middle = by_band.middle;
        metrics.flip_far = by_band.far;
        metrics.near_pixels = by_band.near_pixels;
        metrics.middle_pixels = by_band.middle_pixels;
        metrics.far_pixels = by_band.far_pixels;
    }
    if (flip_map_out) *flip_map_out = std::move(flip_map);

    metrics.nonfinite_pixels = count_nonfinite_pixels(test);

    metrics.columns = columns;
    metrics.light_bleeding = metrics.over_darkening = metrics.penumbra_rmse = nan;
    metrics.umbra_pixels = metrics.lit_pixels = metrics.penumbra_pixels = 0;
    metrics.visibility_mae = metrics.visibility_rmse = metrics.visibility_penumbra_rmse = nan;
    metrics.visibility_pixels = metrics.visibility_penumbra_pixels = 0;
    metrics.visibility_excluded = nan;
    metrics.coverage_mae = metrics.coverage_tile_mae = metrics.coverage_total_error = nan;
    metrics.coverage_pixels = 0;
    metrics.popping_mean = metrics.popping_max = nan;
    if (coverage && columns.coverage) {
        require_same_size(coverage->technique, test, "compute_metrics (technique coverage)");
        require_same_size(coverage->reference, test, "compute_metrics (reference coverage)");
        const CoverageError error = compute_coverage_error(coverage->technique, coverage->reference);
        metrics.coverage_mae = error.mae;
        metrics.coverage_tile_mae = error.tile_mae;
        metrics.coverage_total_error = error.total_error;
        metrics.coverage_pixels = error.pixels;
    }
    if (!visibility || !(columns.visibility || columns.shadow_regions)) return metrics;

    require_same_size(visibility->technique, test, "compute_metrics (technique visibility)");
    require_same_size(visibility->reference, test, "compute_metrics (reference visibility)");
    const PixelClasses classes = classify_pixels(visibility->technique, visibility->reference, options.pixel_classes);
    if (columns.shadow_regions) {
        const ShadowError shadow = compute_shadow_error(test, reference, shadow_region_visibility(visibility->reference, classes),
                                                        options.visibility_epsilon);
        metrics.light_bleeding = shadow.light_bleeding;
        metrics.over_darkening = shadow.over_darkening;
        metrics.penumbra_rmse = shadow.penumbra_rmse;
        metrics.umbra_pixels = shadow.umbra_pixels;
        metrics.lit_pixels = shadow.lit_pixels;
        metrics.penumbra_pixels = shadow.penumbra_pixels;
    }
    if (columns.visibility) {
        const VisibilityError error =
            compute_visibility_error(visibility->technique, visibility->reference, classes, options.visibility_epsilon);
        metrics.visibility_mae = error.mae;
        metrics.visibility_rmse = error.rmse;
        metrics.visibility_penumbra_rmse = error.penumbra_rmse;
        metrics.visibility_pixels = error.pixels;
        metrics.visibility_penumbra_pixels = error.penumbra_pixels;
        metrics.visibility_excluded = error.excluded_fraction;
    }
    return metrics;
}

std::string format_metric_value(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return fmt::format("{:.6g}", value);
}

}  // namespace canopy
