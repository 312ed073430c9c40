#include "metrics/popping.hpp"

#include "metrics/comparable_pair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace canopy {

namespace {

double luminance_at(const Image& image, int x, int y) {
    const float* p = image.at(x, y);
    return 0.2126 * double(p[0]) + 0.7152 * double(p[1]) + 0.0722 * double(p[2]);
}

}  // namespace

PoppingError compute_popping(const std::vector<Image>& technique, const std::vector<const Image*>& reference) {
    if (technique.size() != reference.size() || technique.size() < 2)
        throw std::invalid_argument(fmt::format("compute_popping: {} technique frames and {} reference frames (need the "
                                                "same number, at least 2)",
                                                technique.size(), reference.size()));
    for (size_t k = 0; k < technique.size(); ++k) {
        if (!reference[k]) throw std::invalid_argument("compute_popping: a reference frame is missing");
        require_same_size(technique[k], technique[0], "compute_popping (technique frames)");
        require_same_size(*reference[k], technique[0], "compute_popping (reference frames)");
    }
    PoppingError error;
    const int width = technique[0].width, height = technique[0].height;
    for (size_t k = 1; k < technique.size(); ++k) {
        double sum = 0;
        long long pixels = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const double change_t = luminance_at(technique[k], x, y) - luminance_at(technique[k - 1], x, y);
                const double change_r = luminance_at(*reference[k], x, y) - luminance_at(*reference[k - 1], x, y);
                const double excess = std::abs(change_t - change_r);
                if (!std::isfinite(excess)) continue;
                sum += excess;
                ++pixels;
            }
        const double pair = pixels > 0 ? sum / double(pixels) : std::numeric_limits<double>::quiet_NaN();
        error.per_pair.push_back(pair);
        if (k == 1 || pair > error.max) {
            error.max = pair;
            error.worst_pair = int(k);
        }
        error.mean += pair;
    }
    error.mean /= double(error.per_pair.size());
    return error;
}

}  // namespace canopy
