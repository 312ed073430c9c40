// Structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004) on luminance.
#pragma once

#include "core/image.hpp"

namespace canopy {

// Mean SSIM of the Rec. 709 luminance of the two images, as in Wang et al. 2004:
//  - signal: Y = 0.2126 R + 0.7152 G + 0.0722 B of the *linear* RGB values, clamped to [0, 1]
//    (dynamic range L = 1); no sRGB/gamma encoding is applied;
//  - window: 11x11 circular-symmetric Gaussian, sigma 1.5, normalised to sum 1, applied separably;
//  - constants: C1 = (0.01 L)^2, C2 = (0.03 L)^2;
//  - borders: "valid" region only, as in the authors' reference code (ssim_index.m): a window is
//    evaluated only where it fits inside the image, so the 5-pixel frame has no SSIM value of its own;
//  - pooling: arithmetic mean over those windows whose centre pixel is included (finite in both
//    images, see comparable_pair.hpp; excluded pixels are made equal to the reference first).
// Returns NaN when the image is narrower or shorter than 11 pixels or no window centre is included.
// Symmetric in its arguments; 1 means identical.
double compute_ssim(const Image& test, const Image& reference);

}  // namespace canopy
