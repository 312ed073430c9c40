#include "metrics/comparable_pair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace canopy {

bool pixel_is_finite(const Image& image, int x, int y) {
    const float* p = image.at(x, y);
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(p[3]);
}

long long count_nonfinite_pixels(const Image& image) {
    long long count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (!pixel_is_finite(image, x, y)) ++count;
    return count;
}

void require_same_size(const Image& a, const Image& b, const char* what) {
    auto well_formed = [](const Image& image) {
        return image.width > 0 && image.height > 0 &&
               image.pixels.size() == size_t(image.width) * size_t(image.height) * 4;
    };
    if (!well_formed(a) || !well_formed(b))
        throw std::invalid_argument(fmt::format("{}: images must be non-empty RGBA ({}x{} vs {}x{})", what,
                                                a.width, a.height, b.width, b.height));
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(
            fmt::format("{}: image sizes differ ({}x{} vs {}x{})", what, a.width, a.height, b.width, b.height));
}

ComparablePair make_comparable_pair(const Image& test, const Image& reference) {
    require_same_size(test, reference, "image comparison");
    ComparablePair pair{test, reference, std::vector<std::uint8_t>(size_t(test.width) * size_t(test.height), 1), 0};
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            const bool reference_ok = pixel_is_finite(reference, x, y);
            if (reference_ok && pixel_is_finite(test, x, y)) {
                ++pair.included_count;
                continue;
            }
            pair.included[size_t(y) * size_t(test.width) + size_t(x)] = 0;
            float* t = pair.test.at(x, y);
            float* r = pair.reference.at(x, y);
            for (int c = 0; c < 4; ++c) {
                if (!reference_ok) r[c] = 0.0f;
                t[c] = r[c];
            }
        }
    }
    return pair;
}

}  // namespace canopy
