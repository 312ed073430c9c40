// Image files canopy writes and reads without OpenImageIO: EXR through OpenEXR (with the reference
// cache's attributes), PNG through libpng, in every colour type and depth a height or density map
// may come in, and the errors that name what is wrong.
#include "report/exr_file.hpp"
#include "report/image_files.hpp"
#include "report/png_file.hpp"
#include "support/temp_folder.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <doctest/doctest.h>
#include <png.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace canopy;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void write_raw(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// A PNG written by libpng's simplified API in `format` (an independent writer: not canopy's).
void write_png(const std::filesystem::path& path, int width, int height, png_uint_32 format, const void* pixels,
               const void* colormap = nullptr, png_uint_32 colormap_entries = 0) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(width);
    image.height = png_uint_32(height);
    image.format = format;
    image.colormap_entries = colormap_entries;
    REQUIRE_MESSAGE(png_image_write_to_file(&image, path.c_str(), 0, pixels, 0, colormap), image.message);
}

std::string error_of(const std::filesystem::path& path) {
    try {
        (void)read_image(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("EXR: every float comes back bit for bit, with the attributes, and the same image is the same bytes") {
    test::TempFolder folder;
    Image image(7, 5);
    std::mt19937 random(3);
    std::uniform_real_distribution<float> value(-1e3f, 1e3f);
    for (float& v : image.pixels) v = value(random);
    image.pixels[0] = 1e-42f;  // a denormal
    image.pixels[5] = std::numeric_limits<float>::infinity();
    image.pixels[9] = std::numeric_limits<float>::quiet_NaN();
    ExrAttributes attributes;
    attributes.strings["canopy:key"] = "0123abcd";
    attributes.numbers["canopy:seconds"] = 12.345678901234;
    const std::string bytes = encode_exr(image, attributes);
    CHECK(bytes == encode_exr(image, attributes));
    write_raw(folder.path() / "a.exr", bytes);

    ExrAttributes read_back;
    const Image decoded = read_exr(folder.path() / "a.exr", &read_back);
    REQUIRE(decoded.width == 7);
    REQUIRE(decoded.height == 5);
    CHECK(std::memcmp(decoded.pixels.data(), image.pixels.data(), image.pixels.size() * sizeof(float)) == 0);
    CHECK(read_back.strings.at("canopy:key") == "0123abcd");
    CHECK(read_back.numbers.at("canopy:seconds") == 12.345678901234);

    write_exr(folder.path() / "b.exr", image);  // the run's writer: same pixels through read_image
    const Image again = read_image(folder.path() / "b.exr");
    CHECK(std::memcmp(again.pixels.data(), image.pixels.data(), image.pixels.size() * sizeof(float)) == 0);
}

TEST_CASE("EXR from elsewhere: a half-float grey image with an offset data window reads as grey, opaque") {
    test::TempFolder folder;
    const int width = 3, height = 2;
    Imath::Box2i window({10, 20}, {10 + width - 1, 20 + height - 1});
    Imf::Header header(window, window);
    header.channels().insert("Y", Imf::Channel(Imf::HALF));
    std::vector<half> grey = {half(0.0f), half(0.25f), half(0.5f), half(0.75f), half(1.0f), half(2.0f)};
    Imf::FrameBuffer frame;
    frame.insert("Y", Imf::Slice::Make(Imf::HALF, grey.data(), window, sizeof(half), sizeof(half) * width));
    {
        Imf::OutputFile file((folder.path() / "grey.exr").c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    }
    const Image image = read_image(folder.path() / "grey.exr");
    REQUIRE(image.width == width);
    REQUIRE(image.height == height);
    for (int i = 0; i < width * height; ++i) {
        CAPTURE(i);
        for (int c = 0; c < 3; ++c) CHECK(image.pixels[size_t(i) * 4 + size_t(c)] == float(grey[size_t(i)]));
        CHECK(image.pixels[size_t(i) * 4 + 3] == 1.0f);
    }
}

TEST_CASE("PNG written by canopy: 8-bit sRGB-tagged RGB whose values read back exactly") {
    test::TempFolder folder;
    std::vector<uint8_t> rgb(4 * 3 * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t(i * 7 + 1);
    const std::string bytes = encode_png_rgb8(4, 3, rgb);
    CHECK(contains(bytes, "sRGB"));
    write_raw(folder.path() / "a.png", bytes);
    const Image image = read_image(folder.path() / "a.png");
    REQUIRE(image.width == 4);
    REQUIRE(image.height == 3);
    for (size_t i = 0; i < 12; ++i) {
        CAPTURE(i);
        for (size_t c = 0; c < 3; ++c) CHECK(image.pixels[i * 4 + c] == float(rgb[i * 3 + c]) / 255.0f);
        CHECK(image.pixels[i * 4 + 3] == 1.0f);
    }

    Image linear(2, 1);
    linear.set_opaque(0, 0, {0.0f, 0.5f, 1.0f});
    linear.set_opaque(1, 0, {std::numeric_limits<float>::quiet_NaN(), 2.0f, -1.0f});
    write_png_srgb(folder.path() / "b.png", linear);
    const Image srgb = read_image(folder.path() / "b.png");
    CHECK(srgb.pixels[1] == float(std::lround(linear_to_srgb(0.5f) * 255.0f)) / 255.0f);
    CHECK(srgb.pixels[2] == 1.0f);
    CHECK(srgb.pixels[4] == 1.0f);  // NaN shows white
    CHECK(srgb.pixels[5] == 1.0f);  // clamped
    CHECK(srgb.pixels[6] == 0.0f);
}

TEST_CASE("PNG maps in any form: 16-bit grey exactly, grey with alpha, palettes; values as stored, not decoded") {
    test::TempFolder folder;
    SUBCASE("16-bit grey: every value of the 16 bits, big-endian in the file") {
        const std::vector<uint16_t> grey = {0, 1, 255, 256, 32767, 40000, 65534, 65535};
        write_png(folder.path() / "g16.png", 4, 2, PNG_FORMAT_LINEAR_Y, grey.data());
        const Image image = read_image(folder.path() / "g16.png");
        REQUIRE(image.width == 4);
        for (size_t i = 0; i < grey.size(); ++i) {
            CAPTURE(i);
            for (size_t c = 0; c < 3; ++c) CHECK(image.pixels[i * 4 + c] == float(grey[i]) / 65535.0f);
            CHECK(image.pixels[i * 4 + 3] == 1.0f);
        }
    }
    SUBCASE("8-bit grey with alpha") {
        const std::vector<uint8_t> ga = {10, 255, 128, 0, 255, 77};
        write_png(folder.path() / "ga.png", 3, 1, PNG_FORMAT_GA, ga.data());
        const Image image = read_image(folder.path() / "ga.png");
        for (size_t i = 0; i < 3; ++i) {
            CAPTURE(i);
            for (size_t c = 0; c < 3; ++c) CHECK(image.pixels[i * 4 + c] == float(ga[i * 2]) / 255.0f);
            CHECK(image.pixels[i * 4 + 3] == float(ga[i * 2 + 1]) / 255.0f);
        }
    }
    SUBCASE("a palette expands to its colours") {
        const std::vector<uint8_t> palette = {255, 0, 0, 0, 128, 255};
        const std::vector<uint8_t> indices = {1, 0, 1};
        write_png(folder.path() / "p.png", 3, 1, PNG_FORMAT_RGB_COLORMAP, indices.data(), palette.data(), 2);
        const Image image = read_image(folder.path() / "p.png");
        CHECK(image.pixels[0] == 0.0f);
        CHECK(image.pixels[1] == 128.0f / 255.0f);
        CHECK(image.pixels[2] == 1.0f);
        CHECK(image.pixels[4] == 1.0f);
        CHECK(image.pixels[5] == 0.0f);
        CHECK(image.pixels[8] == 0.0f);
    }
}

TEST_CASE("image files that cannot be read say which file and why") {
    test::TempFolder folder;
    CHECK(contains(error_of(folder.path() / "none.png"), "none.png: No such file or directory"));

    write_raw(folder.path() / "text.png", "P3\n1 1\n255\n0 0 0\n");
    CHECK(contains(error_of(folder.path() / "text.png"), "text.png: it is neither PNG nor OpenEXR"));

    std::vector<uint8_t> rgb(16 * 16 * 3, 100);
    const std::string png = encode_png_rgb8(16, 16, rgb);
    write_raw(folder.path() / "cut.png", png.substr(0, png.size() / 2));
    const std::string cut = error_of(folder.path() / "cut.png");
    CHECK(contains(cut, "cannot read image "));
    CHECK(contains(cut, "cut.png: "));
    CHECK(cut.size() > std::string("cannot read image " + (folder.path() / "cut.png").string() + ": ").size());

    const std::string exr = encode_exr(Image(16, 16));
    write_raw(folder.path() / "cut.exr", exr.substr(0, exr.size() / 2));
    CHECK(contains(error_of(folder.path() / "cut.exr"), "cut.exr: "));

    // A header asking for more than canopy reads is refused before anything is allocated.
    const std::vector<uint8_t> wide(size_t(kMaxImageSide + 1), 0);
    write_png(folder.path() / "wide.png", kMaxImageSide + 1, 1, PNG_FORMAT_GRAY, wide.data());
    CHECK(contains(error_of(folder.path() / "wide.png"), "larger than canopy reads"));
}
