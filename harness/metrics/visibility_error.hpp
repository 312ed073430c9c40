// The technique-isolated error: the visibility a technique's lit pass multiplied into the
// light's irradiance (V_t) against the reference's irradiance-weighted visibility (V_r) at the
// same pixel centres (core/pixel_visibility.hpp). Both sides share one footprint and one shading
// model, so silhouettes, aliasing and shading cancel and what is left is the technique's shadow.
#pragma once

#include "core/image.hpp"
#include "metrics/pixel_classes.hpp"

namespace canopy {

struct VisibilityError {
    double mae;            // mean |V_t - V_r| over the compared pixels (pixel_classes.hpp)
    double rmse;           // sqrt(mean (V_t - V_r)^2) over them
    double penumbra_rmse;  // the same over compared pixels with eps < V_r < 1 - eps
    long long pixels, penumbra_pixels;  // a metric is NaN when its count is 0
    double excluded_fraction;           // of the pixels the light reaches in the reference, not compared
};

// `technique` and `reference` are pixel-visibility images classified into `classes`; throws
// std::invalid_argument on mismatched sizes or an epsilon outside [0, 0.5).
VisibilityError compute_visibility_error(const Image& technique, const Image& reference, const PixelClasses& classes,
                                         double visibility_epsilon);

}  // namespace canopy
