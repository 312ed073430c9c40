// OpenEXR files: canopy's linear float RGBA images, with named attributes in the header (the
// reference cache keeps its key and render statistics there). OpenEXR directly rather than
// through OpenImageIO: Debian's OpenImageIO loads about 260 shared libraries (GDAL, FFmpeg,
// OpenCV, ...) whose start-up cost every canopy process 0.4 s, every test case included.
#pragma once

#include "core/image.hpp"

#include <filesystem>
#include <map>
#include <string>

namespace canopy {

// The largest width or height canopy reads from a file (PNG or EXR): a corrupt header must not
// ask for terabytes.
inline constexpr int kMaxImageSide = 32768;

struct ExrAttributes {
    std::map<std::string, std::string> strings;
    std::map<std::string, double> numbers;  // written as double; float attributes read too
};

// The file's bytes: RGBA 32-bit float, ZIP compression, no time stamp (the same image is the same
// bytes whenever it is written).
std::string encode_exr(const Image& image, const ExrAttributes& attributes = {});

// Reads any scan-line or tiled EXR: R, G, B, A as stored (half and uint converted to float); a file
// with Y but no R reads as grey; missing colour channels read 0 and a missing alpha 1. Fills
// `attributes` with the header's string, double and float attributes when given. Throws
// std::runtime_error("cannot read image PATH: REASON").
Image read_exr(const std::filesystem::path& path, ExrAttributes* attributes = nullptr);

}  // namespace canopy
