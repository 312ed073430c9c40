// Which pixels the technique-isolated error and the shadow-region metrics take part in, from the
// technique's and the reference's pixel-centre visibility images (core/pixel_visibility.hpp).
//
// compared: the reference's pixel centre sees a surface the shadow light reaches (V >= 0), and the
//   raster drew the same surface there (view depths within depth_tolerance, relative) and lit it.
//   Rasterised and ray-cast coverage differ only where a pixel centre lies within rounding of an
//   edge, so this leaves out little (excluded_fraction says how much) and keeps every pixel
//   where both computed a visibility for the same point, silhouettes and contact shadows
//   included: the visibility error needs no band around silhouettes.
// region: compared and off silhouettes. The shadow-region metrics compare luminance with the
//   anti-aliased reference, whose pixels blend the surfaces a silhouette separates; a pixel is on
//   a silhouette when a 4-neighbour sees the background or its reference depth bends: with
//   w = 1 / view depth, which is linear across a plane in screen space,
//   |w(left) + w(right) - 2 w| > silhouette_threshold * w (or the same vertically).
#pragma once

#include "core/image.hpp"

#include <cstdint>
#include <vector>

namespace canopy {

struct PixelClassOptions {
    double depth_tolerance = 1e-3;       // relative view-depth difference of one surface
    double silhouette_threshold = 0.02;  // relative second difference of 1 / depth
};

struct PixelClasses {
    int width = 0, height = 0;
    std::vector<std::uint8_t> compared;  // width * height, row-major, 1 = compared
    std::vector<std::uint8_t> region;    // 1 = compared and off silhouettes
    long long reached = 0;               // reference pixels whose surface the light reaches
    long long compared_count = 0, region_count = 0;
    double excluded_fraction = 0.0;      // 1 - compared / reached; NaN when reached = 0
};

// Throws std::invalid_argument when the images differ in size or are empty. Pixels with a
// non-finite channel in either image are not compared.
PixelClasses classify_pixels(const Image& technique, const Image& reference, const PixelClassOptions& options = {});

// The visibility image compute_shadow_error reads: R = the reference's V, G = 1 on `classes.region`.
Image shadow_region_visibility(const Image& reference, const PixelClasses& classes);

}  // namespace canopy
