// False-colour error images for reports.
#pragma once

#include "core/image.hpp"

#include <vector>

namespace canopy {

// NOTE: unlike other canopy::Image values, the images returned here are NOT linear light: RGB holds
// sRGB-encoded (display-ready) values in [0, 1], alpha = 1. Write them to an 8-bit PNG as they are;
// do not apply another linear-to-sRGB conversion. They have no legend: colour_bar.hpp draws one beside
// them (the runner's error.png and flip.png have it).

// |L_test - L_ref| per pixel (Rec. 709 luminance of the linear RGB values), divided by max_value,
// clamped to [0, 1] and mapped through viridis (dark blue = 0, yellow = max_value or more).
// Pixels where either image has a non-finite channel are drawn pure magenta (1, 0, 1), which viridis
// never produces. Throws std::invalid_argument on mismatched sizes or max_value <= 0.
Image absolute_error_heatmap(const Image& test, const Image& reference, double max_value);

// A FLIP map (see flip.hpp) through FLIP's magma colour map, exactly as the FLIP tool draws it.
// NaN entries (excluded pixels) are drawn pure cyan (0, 1, 1), which magma never produces.
// Throws std::invalid_argument when flip_map.size() != width * height.
Image flip_heatmap(const std::vector<float>& flip_map, int width, int height);

}  // namespace canopy
