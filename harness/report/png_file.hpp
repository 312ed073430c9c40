// PNG files through libpng: canopy writes 8-bit RGB images to look at and reads maps (height,
// density) that users draw. libpng directly rather than through OpenImageIO (see exr_file.hpp).
#pragma once

#include "core/image.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace canopy {

// The bytes of an 8-bit RGB PNG with an sRGB chunk; `rgb` holds width * height * 3 bytes, top row
// first, already encoded for display.
std::string encode_png_rgb8(int width, int height, const std::vector<uint8_t>& rgb);

// Reads a PNG of any colour type and depth as stored, scaled to [0, 1] (no gamma or sRGB
// decoding: a height map's 8- or 16-bit values are what it means): palettes expand to RGB, grey
// fills R, G and B, a missing alpha reads 1 and a tRNS colour key becomes alpha. Throws
// std::runtime_error("cannot read image PATH: REASON").
Image read_png(const std::filesystem::path& path);

}  // namespace canopy
