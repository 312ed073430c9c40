// Perceptually uniform colour maps (matplotlib's magma and viridis, as shipped with NVIDIA's FLIP tool).
#pragma once

#include <array>

namespace canopy {

// One colour map entry, sRGB-encoded (display-ready) values in [0, 1].
using ColormapEntry = std::array<float, 3>;

// 256-entry tables. The values are sRGB-encoded, as in matplotlib and FLIP: write them to an
// 8-bit PNG as they are, without another linear-to-sRGB conversion.
const std::array<ColormapEntry, 256>& magma_colormap();
const std::array<ColormapEntry, 256>& viridis_colormap();

// Looks up value in [0, 1] (clamped; NaN maps to 0) the way the FLIP tool does: entry
// int(value * 255 + 0.5).
ColormapEntry map_to_color(const std::array<ColormapEntry, 256>& colormap, float value);

}  // namespace canopy
