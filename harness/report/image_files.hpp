// Rendered images on disk: linear float EXR for analysis, sRGB PNG for looking at; maps read
// from PNG or EXR (exr_file.hpp, png_file.hpp).
#pragma once

#include "core/image.hpp"

#include <filesystem>

namespace canopy {

void write_exr(const std::filesystem::path& path, const Image& image);         // linear, float RGBA
void write_png_srgb(const std::filesystem::path& path, const Image& image);    // linear -> sRGB, 8-bit RGB
// Writes values already encoded for display (e.g. heat maps) as 8-bit RGB without conversion.
void write_png_display(const std::filesystem::path& path, const Image& image);
// RGBA float, as stored; PNG or OpenEXR, told apart by their first bytes.
Image read_image(const std::filesystem::path& path);

// Linear -> sRGB transfer function, input clamped to [0, 1].
float linear_to_srgb(float linear);

}  // namespace canopy
