#include "metrics/error_maps.hpp"

#include "metrics/colormaps.hpp"
#include "metrics/comparable_pair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace canopy {

Image absolute_error_heatmap(const Image& test, const Image& reference, double max_value) {
    require_same_size(test, reference, "absolute error heatmap");
    if (!(max_value > 0.0))
        throw std::invalid_argument(fmt::format("absolute error heatmap: max_value must be positive, got {}", max_value));
    const ColormapEntry invalid = {1.0f, 0.0f, 1.0f};
    Image heatmap(test.width, test.height);
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            if (!pixel_is_finite(test, x, y) || !pixel_is_finite(reference, x, y)) {
                heatmap.set_opaque(x, y, invalid);
                continue;
            }
            const double difference = std::abs(double(test.luminance(x, y)) - double(reference.luminance(x, y)));
            heatmap.set_opaque(x, y, map_to_color(viridis_colormap(), float(difference / max_value)));
        }
    }
    return heatmap;
}

Image flip_heatmap(const std::vector<float>& flip_map, int width, int height) {
    if (width <= 0 || height <= 0 || flip_map.size() != size_t(width) * size_t(height))
        throw std::invalid_argument(
            fmt::format("FLIP heatmap: map has {} values, expected {}x{}", flip_map.size(), width, height));
    const ColormapEntry invalid = {0.0f, 1.0f, 1.0f};
    Image heatmap(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float value = flip_map[size_t(y) * size_t(width) + size_t(x)];
            heatmap.set_opaque(x, y, std::isnan(value) ? invalid : map_to_color(magma_colormap(), value));
        }
    }
    return heatmap;
}

}  // namespace canopy
