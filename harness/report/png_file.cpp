#include "report/png_file.hpp"

#include "report/exr_file.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace canopy {

namespace {

// libpng reports errors by longjmp. Each setjmp below sits in a function whose locals after it
// are trivially destructible, so the jump skips no destructor; the caller owns every buffer.
struct ReadState {
    char message[256] = "";
};

void record_error(png_structp png, png_const_charp message) {
    auto* state = static_cast<ReadState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message);
    png_longjmp(png, 1);
}

void ignore_warning(png_structp, png_const_charp) {}

struct Layout {
    png_uint_32 width = 0, height = 0;
    int channels = 0;   // after expansion: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    int bit_depth = 0;  // after expansion: 8 or 16
};

bool read_layout(png_structp png, png_infop info, Layout* layout) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    png_set_expand(png);  // palette -> RGB, grey below 8 bits -> 8, tRNS -> alpha
    (void)png_set_interlace_handling(png);
    png_read_update_info(png, info);
    layout->width = png_get_image_width(png, info);
    layout->height = png_get_image_height(png, info);
    layout->channels = png_get_channels(png, info);
    layout->bit_depth = png_get_bit_depth(png, info);
    return true;
}

bool read_rows(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};

// libpng's read structures, destroyed on every way out (an error, an allocation that throws).
struct PngReader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    explicit PngReader(ReadState* state) {
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, state, record_error, ignore_warning);
        if (png) info = png_create_info_struct(png);
    }
    ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;
};

}  // namespace

std::string encode_png_rgb8(int width, int height, const std::vector<uint8_t>& rgb) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(width);
    image.height = png_uint_32(height);
    image.format = PNG_FORMAT_RGB;  // 8-bit, written with an sRGB chunk
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, rgb.data(), 0, nullptr))
        throw std::runtime_error(std::string("cannot encode PNG: ") + image.message);
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, rgb.data(), 0, nullptr))
        throw std::runtime_error(std::string("cannot encode PNG: ") + image.message);
    bytes.resize(size);
    return bytes;
}

Image read_png(const std::filesystem::path& path) {
    const auto fail = [&](const std::string& reason) {
        return std::runtime_error("cannot read image " + path.string() + ": " + reason);
    };
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) throw fail(std::strerror(errno));
    ReadState state;
    PngReader reader(&state);
    if (!reader.info) throw fail("libpng could not start");
    png_init_io(reader.png, file.get());
    Layout layout;
    if (!read_layout(reader.png, reader.info, &layout)) throw fail(state.message);
    if (layout.width > png_uint_32(kMaxImageSide) || layout.height > png_uint_32(kMaxImageSide))
        throw fail("it is " + std::to_string(layout.width) + "x" + std::to_string(layout.height) +
                   ", larger than canopy reads (" + std::to_string(kMaxImageSide) + " a side)");
    const size_t bytes_per_value = size_t(layout.bit_depth) / 8;
    const size_t row_bytes = size_t(layout.width) * size_t(layout.channels) * bytes_per_value;
    std::vector<png_byte> pixels(row_bytes * layout.height);
    std::vector<png_bytep> rows(layout.height);
    for (size_t y = 0; y < layout.height; ++y) rows[y] = pixels.data() + y * row_bytes;
    if (!read_rows(reader.png, reader.info, rows.data())) throw fail(state.message);

    Image image(int(layout.width), int(layout.height));
    const float largest = layout.bit_depth == 16 ? 65535.0f : 255.0f;  // divided, so 51 reads as 51 / 255 exactly
    const auto value = [&](size_t index) {  // 16-bit values are stored big-endian
        const png_byte* p = pixels.data() + index * bytes_per_value;
        return float(bytes_per_value == 2 ? (unsigned(p[0]) << 8) | p[1] : p[0]) / largest;
    };
    const size_t channels = size_t(layout.channels);
    const bool grey = channels < 3;
    const bool alpha = channels == 2 || channels == 4;
    for (size_t i = 0, n = size_t(layout.width) * layout.height; i < n; ++i) {
        float* out = &image.pixels[i * 4];
        for (size_t c = 0; c < 3; ++c) out[c] = value(i * channels + (grey ? 0 : c));
        out[3] = alpha ? value(i * channels + channels - 1) : 1.0f;
    }
    return image;
}

}  // namespace canopy
