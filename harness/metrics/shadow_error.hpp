// Shadow-specific errors, measured against the ray tracer's light visibility.
#pragma once

#include "core/image.hpp"

namespace canopy {

// Reference visibility image (from the ray tracer), per pixel:
//   R = fraction of the shadow light visible from the surface seen at that pixel, in [0, 1];
//   G = 1 where the pixel shows a surface facing the shadow light, 0 elsewhere (background,
//       back-facing). Only pixels with G >= 0.5 take part.
// Classification of a participating pixel, with V = R and eps = visibility_epsilon:
//   umbra: V <= eps;  lit: V >= 1 - eps;  penumbra: eps < V < 1 - eps.
// Pixels whose test, reference or visibility pixel has a non-finite channel are skipped entirely.
// L is the Rec. 709 luminance of the linear RGB values (not clamped).
struct ShadowError {
    double light_bleeding;      // mean over umbra pixels of max(0, L_test - L_ref)
    double over_darkening;      // mean over lit pixels of max(0, L_ref - L_test)
    double penumbra_rmse;       // sqrt(mean over penumbra pixels of (L_test - L_ref)^2)
    long long umbra_pixels;     // each metric above is NaN when its pixel count is 0
    long long lit_pixels;
    long long penumbra_pixels;
};

// Throws std::invalid_argument when the three images differ in size or epsilon is outside [0, 0.5).
ShadowError compute_shadow_error(const Image& test, const Image& reference, const Image& reference_visibility,
                                 double visibility_epsilon);

}  // namespace canopy
