#include "metrics/pixel_classes.hpp"

#include "core/pixel_visibility.hpp"
#include "metrics/comparable_pair.hpp"

#include <cmath>
#include <limits>

namespace canopy {

namespace {

namespace pv = pixel_visibility;

// True when the reference's depth bends or ends around (x, y) along (dx, dy).
bool bends(const Image& reference, int x, int y, int dx, int dy, double threshold) {
    const int x0 = x - dx, y0 = y - dy, x1 = x + dx, y1 = y + dy;
    const bool before = x0 >= 0 && y0 >= 0, after = x1 < reference.width && y1 < reference.height;
    if ((before && !pv::has_surface(reference, x0, y0)) || (after && !pv::has_surface(reference, x1, y1))) return true;
    if (!before || !after) return false;  // the image's border: nothing to compare with
    const double w = 1.0 / reference.at(x, y)[pv::kViewDepth];
    const double w0 = 1.0 / reference.at(x0, y0)[pv::kViewDepth], w1 = 1.0 / reference.at(x1, y1)[pv::kViewDepth];
    return !(std::abs(w0 + w1 - 2.0 * w) <= threshold * w);
}

}  // namespace

PixelClasses classify_pixels(const Image& technique, const Image& reference, const PixelClassOptions& options) {
    require_same_size(technique, reference, "pixel classes");
    PixelClasses classes;
    classes.width = reference.width;
    classes.height = reference.height;
    const size_t count = size_t(reference.width) * size_t(reference.height);
    classes.compared.assign(count, 0);
    classes.region.assign(count, 0);
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            if (!pixel_is_finite(reference, x, y) || !pv::has_surface(reference, x, y) || !pv::is_lit(reference, x, y))
                continue;
            ++classes.reached;
            if (!pixel_is_finite(technique, x, y) || !pv::has_surface(technique, x, y) || !pv::is_lit(technique, x, y))
                continue;
            const double depth = reference.at(x, y)[pv::kViewDepth];
            const double raster_depth = technique.at(x, y)[pv::kViewDepth];
            if (!(std::abs(raster_depth - depth) <= options.depth_tolerance * depth)) continue;  // another surface
            const size_t i = size_t(y) * size_t(reference.width) + size_t(x);
            classes.compared[i] = 1;
            ++classes.compared_count;
            if (bends(reference, x, y, 1, 0, options.silhouette_threshold) ||
                bends(reference, x, y, 0, 1, options.silhouette_threshold))
                continue;
            classes.region[i] = 1;
            ++classes.region_count;
        }
    }
    classes.excluded_fraction = classes.reached > 0
                                    ? 1.0 - double(classes.compared_count) / double(classes.reached)
                                    : std::numeric_limits<double>::quiet_NaN();
    return classes;
}

Image shadow_region_visibility(const Image& reference, const PixelClasses& classes) {
    Image image(reference.width, reference.height);
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            const size_t i = size_t(y) * size_t(reference.width) + size_t(x);
            float* p = image.at(x, y);
            p[0] = classes.region[i] ? reference.at(x, y)[pv::kVisibility] : 0.0f;
            p[1] = classes.region[i] ? 1.0f : 0.0f;
            p[3] = 1.0f;
        }
    return image;
}

}  // namespace canopy
