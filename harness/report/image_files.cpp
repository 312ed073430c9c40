#include "report/image_files.hpp"

#include "report/atomic_file.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace canopy {

namespace {

// Encodes in memory, then writes the bytes atomically: a failed write reports the system's reason
// (OpenImageIO's own file errors do not say why).
void write_with_oiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                     const void* pixels) {
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throw std::runtime_error("cannot write image " + path.string() + ": " + OIIO::geterror());
    if (!out->set_ioproxy(&memory) || !out->open(path.string(), spec) || !out->write_image(type, pixels) || !out->close())
        throw std::runtime_error("cannot encode image " + path.string() + ": " + out->geterror());
    write_bytes_atomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

void write_png_8bit(const std::filesystem::path& path, const Image& image, bool encode_srgb) {
    std::vector<uint8_t> bytes(size_t(image.width) * size_t(image.height) * 3);
    for (size_t i = 0, n = size_t(image.width) * size_t(image.height); i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            float v = image.pixels[i * 4 + size_t(c)];
            if (!std::isfinite(v)) v = 1.0f;  // non-finite pixels show white; the case has failed anyway
            v = encode_srgb ? linear_to_srgb(v) : std::clamp(v, 0.0f, 1.0f);
            bytes[i * 3 + size_t(c)] = uint8_t(std::lround(v * 255.0f));
        }
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    if (encode_srgb) spec.attribute("oiio:ColorSpace", "sRGB");
    write_with_oiio(path, spec, OIIO::TypeDesc::UINT8, bytes.data());
}

}  // namespace

float linear_to_srgb(float linear) {
    float x = std::clamp(linear, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

void write_exr(const std::filesystem::path& path, const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    // No write time in the header (OpenImageIO adds one otherwise): the same image is the same
    // bytes, whenever it is written (a resumed run, a determinism check).
    spec.attribute("DateTime", "");
    write_with_oiio(path, spec, OIIO::TypeDesc::FLOAT, image.pixels.data());
}

void write_png_srgb(const std::filesystem::path& path, const Image& image) { write_png_8bit(path, image, true); }

void write_png_display(const std::filesystem::path& path, const Image& image) { write_png_8bit(path, image, false); }

Image read_image(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw std::runtime_error("cannot read image " + path.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image(spec.width, spec.height);
    std::vector<float> data(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()))
        throw std::runtime_error("cannot read image " + path.string() + ": " + in->geterror());
    for (size_t i = 0, n = size_t(spec.width) * size_t(spec.height); i < n; ++i)
        for (int c = 0; c < 4; ++c)
            image.pixels[i * 4 + size_t(c)] = c < spec.nchannels ? data[i * size_t(spec.nchannels) + size_t(c)] : (c == 3 ? 1.0f : 0.0f);
    return image;
}

}  // namespace canopy
