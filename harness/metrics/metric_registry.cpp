#include "metrics/metric_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace canopy {

namespace {

const MetricGroupInfo kGroups[] = {
    {MetricGroup::whole_image, "", nullptr, "whole image"},
    {MetricGroup::shadow_regions, "shadow_regions", &ErrorColumns::shadow_regions,
     "luminance over the reference's umbra, lit or penumbra pixels"},
    {MetricGroup::visibility, "visibility", &ErrorColumns::visibility,
     "the technique's shadow alone, at the same pixel centres as the reference"},
    {MetricGroup::coverage, "coverage", &ErrorColumns::coverage,
     "the population's coverage of each pixel against the reference's (grass: the blades a representation shows)"},
};

// Compare tolerances: chosen from measurement (README, "Catching regressions"): the quick suite
// rendered by lavapipe's SSE-free code path (GALLIUM_NOSSE=1, 128-bit vectors) moved no metric by
// more than 3.2e-4 of its value (PSNR 1.0e-3 dB, SSIM 1.0e-6) from the AVX-512 path; 256- and
// 512-bit vectors and every thread count gave identical metrics. Tolerances are about 10x that,
// with an absolute floor for metrics near zero. A single pixel's value (max_error) and a pixel's
// place in a sorted order (flip_weighted_median) get 10x more; visibility_excluded is a fraction
// of pixels, allowed to move by a few pixels' worth. Those and the visibility metrics were first
// compared later; the same check (quick suite, GALLIUM_NOSSE=1 against the AVX-512 baseline)
// moved them by at most: visibility_mae 6.1e-4, visibility_rmse 2.8e-4, visibility_penumbra_rmse
// 1.2e-4, flip_weighted_median 8.3e-4, max_error 5.5e-6 of their values; visibility_excluded 0.
constexpr CompareTolerance kRendered{3e-3, 1e-6};

const MetricInfo kMetrics[] = {
    {.name = "mae", .claim = "mae", .column = "MAE", .title = "MAE", .unit = "linear RGB", .better = Better::lower,
     .group = MetricGroup::whole_image, .value = &ImageMetrics::mae, .tolerance = kRendered,
     .doc = "mean abs(test - reference) over the R, G, B values of the compared pixels"},
    {.name = "rmse", .claim = "rmse", .column = "RMSE", .title = "RMSE", .unit = "linear RGB", .better = Better::lower,
     .group = MetricGroup::whole_image, .value = &ImageMetrics::rmse, .tolerance = kRendered,
     .shown = shown_in_markdown, .doc = "root mean square of test - reference over the R, G, B values"},
    {.name = "psnr_db", .claim = "psnr", .column = "PSNR dB", .title = "PSNR", .unit = "dB", .better = Better::higher,
     .group = MetricGroup::whole_image, .value = &ImageMetrics::psnr, .tolerance = {0.0, 0.02},
     .shown = shown_in_markdown | shown_in_console | shown_in_paper_tables, .infinite_key = "psnr_infinite",
     .doc = "20 log10(1 / rmse), peak 1; infinite for identical images"},
    {.name = "max_error", .claim = "max_error", .column = "max error", .title = "largest error", .unit = "linear RGB",
     .better = Better::lower, .group = MetricGroup::whole_image, .value = &ImageMetrics::max_error,
     .tolerance = {3e-2, 1e-5}, .doc = "largest abs(test - reference) of any R, G, B value (its pixel: max_error_pixel)"},
    {.name = "ssim", .claim = "ssim", .column = "SSIM", .title = "SSIM", .unit = "", .better = Better::higher,
     .group = MetricGroup::whole_image, .value = &ImageMetrics::ssim, .tolerance = {0.0, 1e-5},
     .shown = shown_in_markdown, .doc = "mean SSIM of clamped linear luminance, 11x11 Gaussian window (Wang et al. 2004)"},
    {.name = "flip_mean", .claim = "flip", .column = "FLIP", .title = "FLIP", .unit = "", .better = Better::lower,
     .group = MetricGroup::whole_image, .value = &ImageMetrics::flip_mean, .tolerance = kRendered,
     .shown = shown_in_markdown | shown_in_console | shown_in_paper_tables, .doc = "mean of the LDR-FLIP map"},
    {.name = "flip_weighted_median", .claim = "flip_weighted_median", .column = "FLIP median",
     .title = "FLIP weighted median", .unit = "", .better = Better::lower, .group = MetricGroup::whole_image,
     .value = &ImageMetrics::flip_median_weighted, .tolerance = {3e-2, 1e-5},
     .doc = "the FLIP tool's weighted median of the LDR-FLIP map"},
    {.name = "flip_near", .claim = "flip_near", .column = "FLIP near", .title = "FLIP near the eye",
     .unit = "", .better = Better::lower, .group = MetricGroup::whole_image, .value = &ImageMetrics::flip_near,
     .tolerance = kRendered, .shown = shown_in_markdown | shown_in_paper_tables, .only_when_measured = true,
     .doc = "mean of the LDR-FLIP map over the pixels whose reference surface is nearer than [reference] "
            "distance_bands' first distance",
     .band = DistanceBand::near},
    {.name = "flip_middle", .claim = "flip_middle", .column = "FLIP middle", .title = "FLIP at middle distance",
     .unit = "", .better = Better::lower, .group = MetricGroup::whole_image, .value = &ImageMetrics::flip_middle,
     .tolerance = kRendered, .shown = shown_in_markdown | shown_in_paper_tables, .only_when_measured = true,
     .doc = "the same between distance_bands' two distances", .band = DistanceBand::middle},
    {.name = "flip_far", .claim = "flip_far", .column = "FLIP far", .title = "FLIP far from the eye", .unit = "",
     .better = Better::lower, .group = MetricGroup::whole_image, .value = &ImageMetrics::flip_far,
     .tolerance = kRendered, .shown = shown_in_markdown | shown_in_paper_tables, .only_when_measured = true,
     .doc = "the same at or beyond distance_bands' second distance", .band = DistanceBand::far},
    {.name = "light_bleeding", .claim = "bleeding", .column = "bleeding", .title = "light bleeding",
     .unit = "luminance", .better = Better::lower, .group = MetricGroup::shadow_regions,
     .value = &ImageMetrics::light_bleeding, .tolerance = kRendered,
     .shown = shown_in_markdown | shown_in_paper_tables,
     .doc = "mean excess luminance over the reference's full-umbra pixels"},
    {.name = "over_darkening", .claim = "over_darkening", .column = "over-dark", .title = "over-darkening",
     .unit = "luminance", .better = Better::lower, .group = MetricGroup::shadow_regions,
     .value = &ImageMetrics::over_darkening, .tolerance = kRendered, .shown = shown_in_markdown,
     .doc = "mean missing luminance over the reference's fully lit pixels"},
    {.name = "penumbra_rmse", .claim = "penumbra_rmse", .column = "penumbra RMSE", .title = "penumbra RMSE",
     .unit = "luminance", .better = Better::lower, .group = MetricGroup::shadow_regions,
     .value = &ImageMetrics::penumbra_rmse, .tolerance = kRendered,
     .shown = shown_in_markdown | shown_in_console | shown_in_paper_tables,
     .doc = "luminance RMSE over the reference's penumbra pixels (0 < V < 1)"},
    {.name = "visibility_mae", .claim = "visibility_mae", .column = "V MAE", .title = "visibility MAE",
     .unit = "visibility", .better = Better::lower, .group = MetricGroup::visibility,
     .value = &ImageMetrics::visibility_mae, .tolerance = kRendered, .shown = shown_in_markdown,
     .doc = "mean abs(V_technique - V_reference) over the compared pixel centres"},
    {.name = "visibility_rmse", .claim = "visibility_rmse", .column = "V RMSE", .title = "visibility RMSE",
     .unit = "visibility", .better = Better::lower, .group = MetricGroup::visibility,
     .value = &ImageMetrics::visibility_rmse, .tolerance = kRendered,
     .shown = shown_in_markdown | shown_in_console | shown_in_paper_tables,
     .doc = "RMSE of V_technique - V_reference over the compared pixel centres"},
    {.name = "visibility_penumbra_rmse", .claim = "visibility_penumbra_rmse", .column = "V penumbra RMSE",
     .title = "visibility RMSE in the penumbra", .unit = "visibility", .better = Better::lower,
     .group = MetricGroup::visibility, .value = &ImageMetrics::visibility_penumbra_rmse, .tolerance = kRendered,
     .shown = shown_in_markdown | shown_in_paper_tables,
     .doc = "the same RMSE over compared pixels the reference sees in penumbra"},
    {.name = "visibility_excluded", .claim = "visibility_excluded", .column = "V excluded %",
     .title = "pixels left out of the visibility comparison", .unit = "fraction of pixels", .better = Better::lower,
     .group = MetricGroup::visibility, .value = &ImageMetrics::visibility_excluded, .tolerance = {0.0, 1e-4},
     .shown = shown_in_markdown, .percent = true,
     .doc = "of the pixels the light reaches in the reference, the fraction the raster did not see or light"},
    {.name = "coverage_mae", .claim = "coverage_mae", .column = "cov MAE", .title = "coverage MAE",
     .unit = "fraction of a pixel", .better = Better::lower, .group = MetricGroup::coverage,
     .value = &ImageMetrics::coverage_mae, .tolerance = kRendered, .shown = shown_in_markdown,
     .doc = "mean abs(c_technique - c_reference) of the population coverage over covered pixels (aliasing included)"},
    {.name = "coverage_tile_mae", .claim = "coverage_tile_mae", .column = "cov tile MAE",
     .title = "coverage MAE over 8x8 tiles", .unit = "fraction of a pixel", .better = Better::lower,
     .group = MetricGroup::coverage, .value = &ImageMetrics::coverage_tile_mae, .tolerance = kRendered,
     .shown = shown_in_markdown | shown_in_console | shown_in_paper_tables,
     .doc = "mean over 8x8-pixel tiles with coverage of abs(mean c_technique - mean c_reference): "
            "where the grass is, with pixel-scale aliasing averaged out"},
    {.name = "coverage_total_error", .claim = "coverage_total_error", .column = "cov total %",
     .title = "coverage gained or lost over the image", .unit = "fraction of the true coverage",
     .better = Better::lower, .group = MetricGroup::coverage, .value = &ImageMetrics::coverage_total_error,
     .tolerance = kRendered, .shown = shown_in_markdown | shown_in_paper_tables, .percent = true,
     .doc = "abs(sum c_technique - sum c_reference) / sum c_reference"},
    {.name = "popping_mean", .claim = "popping", .column = "popping", .title = "popping along the camera path",
     .unit = "luminance", .better = Better::lower, .group = MetricGroup::whole_image,
     .value = &ImageMetrics::popping_mean, .tolerance = kRendered,
     .shown = shown_in_markdown | shown_in_console | shown_in_paper_tables, .only_when_measured = true,
     .doc = "mean over consecutive path frames of mean abs(change of the technique's luminance - change of the "
            "reference's): what the technique changes that the scene does not ([camera_path] popping = true)"},
    {.name = "popping_max", .claim = "popping_max", .column = "popping max", .title = "worst popping between two frames",
     .unit = "luminance", .better = Better::lower, .group = MetricGroup::whole_image,
     .value = &ImageMetrics::popping_max, .tolerance = kRendered, .shown = shown_in_markdown,
     .only_when_measured = true, .doc = "the same for the pair of consecutive path frames where it is largest"},
};

const MetricCountInfo kCounts[] = {
    {"nonfinite_pixels", "", MetricGroup::whole_image, &ImageMetrics::nonfinite_pixels,
     "test pixels with NaN or Inf in any channel"},
    {"near_pixels", "", MetricGroup::whole_image, &ImageMetrics::near_pixels,
     "pixels in the near distance band ([reference] distance_bands; 0 without)"},
    {"middle_pixels", "", MetricGroup::whole_image, &ImageMetrics::middle_pixels,
     "pixels in the middle distance band"},
    {"far_pixels", "", MetricGroup::whole_image, &ImageMetrics::far_pixels, "pixels in the far distance band"},
    {"umbra_pixels", "umbra", MetricGroup::shadow_regions, &ImageMetrics::umbra_pixels,
     "the reference's pixels in full umbra (V <= 1e-3), off silhouettes"},
    {"lit_pixels", "lit", MetricGroup::shadow_regions, &ImageMetrics::lit_pixels,
     "the reference's fully lit pixels (V >= 1 - 1e-3), off silhouettes"},
    {"penumbra_pixels", "penumbra", MetricGroup::shadow_regions, &ImageMetrics::penumbra_pixels,
     "the reference's penumbra pixels (0 < V < 1), off silhouettes"},
    {"visibility_pixels", "", MetricGroup::visibility, &ImageMetrics::visibility_pixels,
     "pixel centres the visibility comparison took"},
    {"visibility_penumbra_pixels", "", MetricGroup::visibility, &ImageMetrics::visibility_penumbra_pixels,
     "of those, the ones in the reference's penumbra"},
    {"coverage_pixels", "", MetricGroup::coverage, &ImageMetrics::coverage_pixels,
     "pixels the technique or the reference covers with the population"},
};

std::span<const MetricInfo> g_metrics = kMetrics;
std::span<const MetricCountInfo> g_counts = kCounts;

}  // namespace

const char* to_string(Better better) { return better == Better::lower ? "lower" : "higher"; }

std::span<const MetricGroupInfo> metric_groups() { return kGroups; }

const MetricGroupInfo& group_info(MetricGroup group) {
    for (const MetricGroupInfo& g : kGroups)
        if (g.group == group) return g;
    throw std::logic_error("metric group without an entry in metric_registry.cpp");
}

bool group_declared(MetricGroup group, const ErrorColumns& columns) {
    const MetricGroupInfo& g = group_info(group);
    return g.declared == nullptr || columns.*g.declared;
}

double MetricInfo::meaningful_value(const ImageMetrics& m) const {
    return group_declared(group, m.columns) ? m.*value : std::numeric_limits<double>::quiet_NaN();
}

std::span<const MetricInfo> registered_metrics() { return g_metrics; }
std::span<const MetricCountInfo> registered_metric_counts() { return g_counts; }

const MetricInfo* find_metric(std::string_view name) {
    for (const MetricInfo& m : g_metrics)
        if (m.name == name) return &m;
    return nullptr;
}

const MetricInfo* find_claim_metric(std::string_view claim) {
    for (const MetricInfo& m : g_metrics)
        if (m.claim == claim) return &m;
    return nullptr;
}

std::vector<std::string> claim_metric_names() {
    std::vector<std::string> names{std::string(kTimeClaim)};
    for (const MetricInfo& m : g_metrics) names.emplace_back(m.claim);
    return names;
}

Better claim_metric_better(std::string_view claim) {
    if (claim == kTimeClaim) return Better::lower;
    if (const MetricInfo* m = find_claim_metric(claim)) return m->better;
    throw std::invalid_argument(fmt::format("'{}' is no claim metric", claim));
}

ScopedMetricRegistry::ScopedMetricRegistry(std::span<const MetricInfo> metrics, std::span<const MetricCountInfo> counts)
    : previous_metrics_(g_metrics), previous_counts_(g_counts) {
    g_metrics = metrics;
    g_counts = counts;
}

ScopedMetricRegistry::~ScopedMetricRegistry() {
    g_metrics = previous_metrics_;
    g_counts = previous_counts_;
}

}  // namespace canopy
