#include "metrics/visibility_error.hpp"

#include "core/pixel_visibility.hpp"
#include "metrics/comparable_pair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace canopy {

VisibilityError compute_visibility_error(const Image& technique, const Image& reference, const PixelClasses& classes,
                                         double visibility_epsilon) {
    require_same_size(technique, reference, "visibility error");
    if (classes.width != reference.width || classes.height != reference.height)
        throw std::invalid_argument("visibility error: the pixel classes are of another image size");
    if (!(visibility_epsilon >= 0.0 && visibility_epsilon < 0.5))
        throw std::invalid_argument(
            fmt::format("visibility error: visibility epsilon must be in [0, 0.5), got {}", visibility_epsilon));
    namespace pv = pixel_visibility;
    double absolute_sum = 0.0, squared_sum = 0.0, penumbra_squared_sum = 0.0;
    VisibilityError error{0.0, 0.0, 0.0, 0, 0, classes.excluded_fraction};
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            if (!classes.compared[size_t(y) * size_t(reference.width) + size_t(x)]) continue;
            const double truth = reference.at(x, y)[pv::kVisibility];
            const double difference = double(technique.at(x, y)[pv::kVisibility]) - truth;
            absolute_sum += std::abs(difference);
            squared_sum += difference * difference;
            ++error.pixels;
            if (truth > visibility_epsilon && truth < 1.0 - visibility_epsilon) {
                penumbra_squared_sum += difference * difference;
                ++error.penumbra_pixels;
            }
        }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    error.mae = error.pixels > 0 ? absolute_sum / double(error.pixels) : nan;
    error.rmse = error.pixels > 0 ? std::sqrt(squared_sum / double(error.pixels)) : nan;
    error.penumbra_rmse = error.penumbra_pixels > 0 ? std::sqrt(penumbra_squared_sum / double(error.penumbra_pixels)) : nan;
    return error;
}

}  // namespace canopy
