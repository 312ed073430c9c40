#include "metrics/shadow_error.hpp"

#include "metrics/comparable_pair.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace canopy {

ShadowError compute_shadow_error(const Image& test, const Image& reference, const Image& reference_visibility,
                                 double visibility_epsilon) {
    require_same_size(test, reference, "shadow error");
    require_same_size(reference, reference_visibility, "shadow error (visibility)");
    if (!(visibility_epsilon >= 0.0 && visibility_epsilon < 0.5))
        throw std::invalid_argument(
            fmt::format("shadow error: visibility epsilon must be in [0, 0.5), got {}", visibility_epsilon));

    double bleeding_sum = 0.0, darkening_sum = 0.0, penumbra_squared_sum = 0.0;
    ShadowError result{0.0, 0.0, 0.0, 0, 0, 0};
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            if (!pixel_is_finite(test, x, y) || !pixel_is_finite(reference, x, y) ||
                !pixel_is_finite(reference_visibility, x, y))
                continue;
            const float* visibility = reference_visibility.at(x, y);
            if (!(visibility[1] >= 0.5f)) continue;  // not a light-facing surface
            const double v = visibility[0];
            const double test_luminance = test.luminance(x, y);
            const double reference_luminance = reference.luminance(x, y);
            if (v <= visibility_epsilon) {
                bleeding_sum += std::max(0.0, test_luminance - reference_luminance);
                ++result.umbra_pixels;
            } else if (v >= 1.0 - visibility_epsilon) {
                darkening_sum += std::max(0.0, reference_luminance - test_luminance);
                ++result.lit_pixels;
            } else {
                const double difference = test_luminance - reference_luminance;
                penumbra_squared_sum += difference * difference;
                ++result.penumbra_pixels;
            }
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    result.light_bleeding = result.umbra_pixels > 0 ? bleeding_sum / double(result.umbra_pixels) : nan;
    result.over_darkening = result.lit_pixels > 0 ? darkening_sum / double(result.lit_pixels) : nan;
    result.penumbra_rmse =
        result.penumbra_pixels > 0 ? std::sqrt(penumbra_squared_sum / double(result.penumbra_pixels)) : nan;
    return result;
}

}  // namespace canopy
