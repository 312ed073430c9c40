// Error by distance from the eye (an experiment's [reference] distance_bands): each pixel is near,
// middle or far by the distance from the eye to the surface the reference sees through its centre
// (the pixel-centre render, core/pixel_visibility.hpp), so that a level-of-detail scheme's far
// band is scored on the pixels it draws and not diluted by, or blamed for, the near ones. The
// reference's surface decides, not the technique's, so every technique of a scene is scored over
// the same pixels. Background pixels belong to no band.
#pragma once

#include "core/image.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <vector>

namespace canopy {

// near: distance < middle_from; middle: middle_from <= distance < far_from; far: far_from <= distance.
struct DistanceBands {
    double middle_from = 0.0;
    double far_from = 0.0;
};

enum class DistanceBand : std::uint8_t { none = 0, near = 1, middle = 2, far = 3 };

// The band of every pixel (width * height, row-major) from the reference's pixel-centre visibility
// image (its view depth and surface channels) and the camera it was rendered with: the distance
// along the pixel centre's ray is the view depth over the ray's cosine with the view axis.
// Throws std::invalid_argument for an empty image or bands that are not 0 <= middle_from <= far_from.
std::vector<DistanceBand> classify_distances(const Image& reference_pixel_visibility, const Camera& camera,
                                             const DistanceBands& bands);

// Mean of `per_pixel` over the pixels of each band, finite values only; NaN for a band with none.
struct BandMeans {
    double near = 0, middle = 0, far = 0;
    long long near_pixels = 0, middle_pixels = 0, far_pixels = 0;
};
BandMeans band_means(const std::vector<float>& per_pixel, const std::vector<DistanceBand>& bands);

}  // namespace canopy
