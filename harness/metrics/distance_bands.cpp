#include "metrics/distance_bands.hpp"

#include "core/pixel_visibility.hpp"
#include "scene/camera.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace canopy {

std::vector<DistanceBand> classify_distances(const Image& reference_pixel_visibility, const Camera& camera,
                                             const DistanceBands& bands) {
    const Image& image = reference_pixel_visibility;
    if (image.width <= 0 || image.height <= 0)
        throw std::invalid_argument("classify_distances: the reference's pixel-centre image is empty");
    if (!(bands.middle_from >= 0.0 && bands.middle_from <= bands.far_from && std::isfinite(bands.far_from)))
        throw std::invalid_argument(fmt::format("classify_distances: bands must satisfy 0 <= middle_from <= far_from, got "
                                                "{} and {}", bands.middle_from, bands.far_from));
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    std::vector<DistanceBand> out(size_t(image.width) * size_t(image.height), DistanceBand::none);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!pixel_visibility::has_surface(image, x, y)) continue;
            const float depth = image.at(x, y)[pixel_visibility::kViewDepth];
            // The pixel-centre render traces the ray through (x + 0.5, y + 0.5).
            const Ray ray = primary_ray(camera, image.width, image.height, float(x) + 0.5f, float(y) + 0.5f);
            const double cosine = glm::dot(ray.direction, forward);
            const double distance = double(depth) / cosine;
            if (!std::isfinite(distance) || cosine <= 0.0) continue;
            out[size_t(y) * size_t(image.width) + size_t(x)] = distance < bands.middle_from ? DistanceBand::near
                                                               : distance < bands.far_from  ? DistanceBand::middle
                                                                                            : DistanceBand::far;
        }
    return out;
}

BandMeans band_means(const std::vector<float>& per_pixel, const std::vector<DistanceBand>& bands) {
    if (per_pixel.size() != bands.size())
        throw std::invalid_argument(fmt::format("band_means: {} values for {} pixels", per_pixel.size(), bands.size()));
    double sum[4] = {0, 0, 0, 0};
    long long count[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < per_pixel.size(); ++i) {
        if (!std::isfinite(per_pixel[i])) continue;
        const auto band = size_t(bands[i]);
        sum[band] += per_pixel[i];
        ++count[band];
    }
    const auto mean = [&](DistanceBand band) {
        const auto b = size_t(band);
        return count[b] > 0 ? sum[b] / double(count[b]) : std::numeric_limits<double>::quiet_NaN();
    };
    BandMeans m;
    m.near = mean(DistanceBand::near);
    m.middle = mean(DistanceBand::middle);
    m.far = mean(DistanceBand::far);
    m.near_pixels = count[size_t(DistanceBand::near)];
    m.middle_pixels = count[size_t(DistanceBand::middle)];
    m.far_pixels = count[size_t(DistanceBand::far)];
    return m;
}

}  // namespace canopy
