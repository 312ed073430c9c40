#include "metrics/pixel_error.hpp"

#include "metrics/comparable_pair.hpp"

#include <cmath>
#include <limits>

namespace canopy {

PixelError compute_pixel_error(const Image& test, const Image& reference) {
    const ComparablePair pair = make_comparable_pair(test, reference);
    PixelError result;
    result.included_pixels = pair.included_count;
    if (pair.included_count == 0) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        result.mae = result.rmse = result.psnr = result.max_error = nan;
        return result;
    }
    double sum_abs = 0.0, sum_squared = 0.0;
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x) {
            const size_t pixel = size_t(y) * size_t(test.width) + size_t(x);
            if (!pair.included[pixel]) continue;
            const float* t = pair.test.at(x, y);
            const float* r = pair.reference.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double error = std::abs(double(t[c]) - double(r[c]));
                sum_abs += error;
                sum_squared += error * error;
                if (error > result.max_error || result.max_x < 0) {  // strictly larger: the first on ties
                    result.max_error = error;
                    result.max_x = x;
                    result.max_y = y;
                }
            }
        }
    const double values = 3.0 * double(pair.included_count);
    result.mae = sum_abs / values;
    result.rmse = std::sqrt(sum_squared / values);
    result.psnr = result.rmse > 0.0 ? 20.0 * std::log10(1.0 / result.rmse) : std::numeric_limits<double>::infinity();
    return result;
}

}  // namespace canopy
