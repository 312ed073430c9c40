// Per-channel pixel error statistics (MAE, RMSE, PSNR, max error).
#pragma once

#include "core/image.hpp"

namespace canopy {

struct PixelError {
    double mae = 0.0;        // mean |test - ref| over the R, G, B channels of the included pixels
    double rmse = 0.0;       // sqrt(mean (test - ref)^2) over the same values
    double psnr = 0.0;       // 20 * log10(1 / rmse), peak 1.0; +infinity when rmse == 0
    double max_error = 0.0;  // largest |test - ref| of any R, G, B channel
    int max_x = -1;          // pixel of max_error (the first one in row-major order on ties)
    int max_y = -1;
    long long included_pixels = 0;
};

// Linear RGB values as stored (no clamping, no encoding); alpha is ignored. Pixels where either
// image has a non-finite channel are left out of every statistic (see comparable_pair.hpp); when no
// pixel is left all fields are NaN and max_x = max_y = -1.
// Sums in double over the R, G, B values of the included pixels. The peak of PSNR is 1.0, not
// OpenImageIO's max(1, largest value in either image), which canopy computed these with before.
PixelError compute_pixel_error(const Image& test, const Image& reference);

}  // namespace canopy
