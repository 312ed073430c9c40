// Which error columns measure something for a technique, declared by its family
// (Technique::error_columns). The whole-image errors (MAE, RMSE, PSNR, SSIM, FLIP) always do:
// they answer "how far is the image from the truth". The others compare the technique's
// visibility or shadow regions with the reference's at the raster's own pixel centres, which
// means something only where the technique keeps the scene's surfaces (the primary hits) and
// shades them with canopy's lit pass; reports show "n/a" for a column a technique does not
// declare.
#pragma once

namespace canopy {

// Which metric belongs to which group: metrics/metric_registry.cpp (MetricGroup).
struct ErrorColumns {
    // The visibility the lit pass multiplied into the light's irradiance against the reference's
    // at the same primary hits ("how wrong is the technique's shadow").
    bool visibility = false;
    // Luminance errors over the reference's umbra, lit and penumbra pixels.
    bool shadow_regions = false;
    // The technique's population coverage per pixel (its colour target's alpha: the fraction of the
    // pixel its blades cover) against the reference's fraction of pixel samples that hit the
    // population (metrics/coverage_error.hpp). For a family that changes the primary hits (grass
    // representations). A family's alpha carries visibility or coverage, so not both.
    bool coverage = false;

    // Whether the declaration can be kept: visibility and coverage both read the colour alpha.
    bool consistent() const { return !(coverage && visibility); }

    bool operator==(const ErrorColumns&) const = default;
};

}  // namespace canopy
