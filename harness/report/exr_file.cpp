#include "report/exr_file.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string_view>

namespace canopy {

namespace {

// OpenEXR writes its line-offset table last and seeks back to it: a stream that can seek.
class MemoryStream : public Imf::OStream {
public:
    MemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (position_ + size_t(n) > bytes_.size()) bytes_.resize(position_ + size_t(n));
        std::memcpy(bytes_.data() + position_, c, size_t(n));
        position_ += size_t(n);
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = size_t(position); }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
    size_t position_ = 0;
};

constexpr size_t kPixelBytes = 4 * sizeof(float);

}  // namespace

std::string encode_exr(const Image& image, const ExrAttributes& attributes) {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    const char* channels[4] = {"R", "G", "B", "A"};
    for (const char* name : channels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    for (const auto& [name, value] : attributes.strings) header.insert(name, Imf::StringAttribute(value));
    for (const auto& [name, value] : attributes.numbers) header.insert(name, Imf::DoubleAttribute(value));

    Imf::FrameBuffer frame;
    // OpenEXR only reads through these pointers when writing.
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data()));
    for (int c = 0; c < 4; ++c)
        frame.insert(channels[c], Imf::Slice(Imf::FLOAT, base + size_t(c) * sizeof(float), kPixelBytes,
                                             kPixelBytes * size_t(image.width)));
    MemoryStream stream;
    {
        Imf::OutputFile file(stream, header);  // the destructor writes the offset table
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    }
    return stream.take();
}

Image read_exr(const std::filesystem::path& path, ExrAttributes* attributes) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const int width = window.max.x - window.min.x + 1;
        const int height = window.max.y - window.min.y + 1;
        if (width <= 0 || height <= 0) throw std::runtime_error("its data window is empty");
        if (width > kMaxImageSide || height > kMaxImageSide)
            throw std::runtime_error("it is " + std::to_string(width) + "x" + std::to_string(height) +
                                     ", larger than canopy reads (" + std::to_string(kMaxImageSide) + " a side)");
        Image image(width, height);
        const Imf::ChannelList& present = header.channels();
        const bool grey = !present.findChannel("R") && present.findChannel("Y");
        Imf::FrameBuffer frame;
        char* base = reinterpret_cast<char*>(image.pixels.data());
        const char* names[4] = {grey ? "Y" : "R", "G", "B", "A"};
        for (int c = 0; c < (grey ? 1 : 4); ++c)
            frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, base + size_t(c) * sizeof(float), window, kPixelBytes,
                                                    kPixelBytes * size_t(width), 1, 1, c == 3 ? 1.0 : 0.0));
        if (grey) frame.insert("A", Imf::Slice::Make(Imf::FLOAT, base + 3 * sizeof(float), window, kPixelBytes,
                                                     kPixelBytes * size_t(width), 1, 1, 1.0));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (grey)
            for (size_t i = 0, n = size_t(width) * size_t(height); i < n; ++i)
                image.pixels[i * 4 + 1] = image.pixels[i * 4 + 2] = image.pixels[i * 4];
        if (attributes) {
            // By type name: dynamic_cast across OpenEXR's shared library is not to be relied on.
            for (auto it = header.begin(); it != header.end(); ++it) {
                const std::string_view type = it.attribute().typeName();
                if (type == "string")
                    attributes->strings[it.name()] = static_cast<const Imf::StringAttribute&>(it.attribute()).value();
                else if (type == "double")
                    attributes->numbers[it.name()] = static_cast<const Imf::DoubleAttribute&>(it.attribute()).value();
                else if (type == "float")
                    attributes->numbers[it.name()] = double(static_cast<const Imf::FloatAttribute&>(it.attribute()).value());
            }
        }
        return image;
    } catch (const std::exception& e) {
        throw std::runtime_error("cannot read image " + path.string() + ": " + e.what());
    }
}

}  // namespace canopy
