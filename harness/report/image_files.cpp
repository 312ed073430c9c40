#include "report/image_files.hpp"

#include "report/atomic_file.hpp"
#include "report/exr_file.hpp"
#include "report/png_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace canopy {

namespace {

void write_png_8bit(const std::filesystem::path& path, const Image& image, bool encode_srgb) {
    std::vector<uint8_t> bytes(size_t(image.width) * size_t(image.height) * 3);
    for (size_t i = 0, n = size_t(image.width) * size_t(image.height); i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            float v = image.pixels[i * 4 + size_t(c)];
            if (!std::isfinite(v)) v = 1.0f;  // non-finite pixels show white; the case has failed anyway
            v = encode_srgb ? linear_to_srgb(v) : std::clamp(v, 0.0f, 1.0f);
            bytes[i * 3 + size_t(c)] = uint8_t(std::lround(v * 255.0f));
        }
    // Encoded in memory, then written atomically: a failed write says the system's reason.
    write_bytes_atomically(path, encode_png_rgb8(image.width, image.height, bytes));
}

}  // namespace

float linear_to_srgb(float linear) {
    float x = std::clamp(linear, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

void write_exr(const std::filesystem::path& path, const Image& image) { write_bytes_atomically(path, encode_exr(image)); }

void write_png_srgb(const std::filesystem::path& path, const Image& image) { write_png_8bit(path, image, true); }

void write_png_display(const std::filesystem::path& path, const Image& image) { write_png_8bit(path, image, false); }

Image read_image(const std::filesystem::path& path) {
    // By content, not by name: a map saved as .PNG, or an EXR named .tmp, reads all the same.
    char magic[8] = {};
    {
        std::ifstream file(path, std::ios::binary);
        if (!file) throw std::runtime_error("cannot read image " + path.string() + ": " + std::strerror(errno));
        file.read(magic, sizeof magic);
    }
    static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char exr_magic[4] = {0x76, 0x2f, 0x31, 0x01};
    if (std::memcmp(magic, png_magic, sizeof png_magic) == 0) return read_png(path);
    if (std::memcmp(magic, exr_magic, sizeof exr_magic) == 0) return read_exr(path);
    throw std::runtime_error("cannot read image " + path.string() +
                             ": it is neither PNG nor OpenEXR, the two formats canopy reads (convert it, e.g. "
                             "`oiiotool in.tif -o out.png`)");
}

}  // namespace canopy
