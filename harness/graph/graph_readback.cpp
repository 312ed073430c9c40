#include "graph/graph_readback.hpp"

#include "gpu/format_names.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace canopy {

namespace {

float half_to_float(uint16_t h) {
    const uint32_t sign = uint32_t(h >> 15), exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    float value;
    if (exponent == 0) value = std::ldexp(float(mantissa), -24);
    else if (exponent == 31) value = mantissa ? NAN : INFINITY;
    else value = std::ldexp(float(mantissa | 0x400), int(exponent) - 25);
    return sign ? -value : value;
}

}  // namespace

Image read_graph_image(const GpuContext& gpu, GraphExecutor& executor, const std::string& name, uint32_t mip,
                       uint32_t layer) {
    GraphImage& image = executor.resources().image(name);
    size_t channels = 0, bytes_per_channel = 4;
    switch (image.format()) {
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_D32_SFLOAT: channels = 1; break;
        case VK_FORMAT_R32G32_SFLOAT: channels = 2; break;
        case VK_FORMAT_R32G32B32A32_SFLOAT: channels = 4; break;
        case VK_FORMAT_R16G16B16A16_SFLOAT: channels = 4, bytes_per_channel = 2; break;
        case VK_FORMAT_R16_SFLOAT: channels = 1, bytes_per_channel = 2; break;
        default:
            throw std::logic_error(fmt::format("read_image('{}'): format {} is not supported", name, format_name(image.format())));
    }
    if (image.decl().samples != 1) throw std::logic_error(fmt::format("read_image('{}'): multisampled", name));
    const uint32_t w = image.width(mip), h = image.height(mip);
    const size_t texels = size_t(w) * h;
    MemoryLedger readback_ledger;  // transient, not charged to the technique
    Buffer staging(gpu, readback_ledger, "readback", texels * channels * bytes_per_channel,
                   VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    const Subresource one{mip, 1, layer, 1};
    const VkImageLayout before = image.layout(mip, layer);
    VkCommandBuffer commands = gpu.begin_commands();
    executor.transition(commands, image, one, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect(), mip, layer, 1};
    region.imageExtent = {w, h, 1};
    vkCmdCopyImageToBuffer(commands, image.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    if (before != VK_IMAGE_LAYOUT_UNDEFINED) executor.transition(commands, image, one, before);
    gpu.submit_and_wait(commands);

    Image out{int(w), int(h)};
    const auto* bytes = static_cast<const std::byte*>(staging.mapped());
    for (size_t i = 0; i < texels; ++i) {
        float rgba[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        for (size_t c = 0; c < channels; ++c) {
            const std::byte* p = bytes + (i * channels + c) * bytes_per_channel;
            if (bytes_per_channel == 4) {
                std::memcpy(&rgba[c], p, 4);
            } else {
                uint16_t half;
                std::memcpy(&half, p, 2);
                rgba[c] = half_to_float(half);
            }
        }
        std::memcpy(&out.pixels[4 * i], rgba, sizeof(rgba));
    }
    return out;
}

std::vector<std::byte> read_graph_buffer(const GpuContext& gpu, const GraphExecutor& executor, const std::string& name) {
    const Buffer& buffer = executor.resources().buffer(name);
    std::vector<std::byte> bytes(buffer.size());
    if (buffer.mapped()) {
        std::memcpy(bytes.data(), buffer.mapped(), bytes.size());
        return bytes;
    }
    MemoryLedger readback_ledger;
    Buffer staging(gpu, readback_ledger, "readback", buffer.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    VkCommandBuffer commands = gpu.begin_commands();
    VkBufferCopy region{0, 0, buffer.size()};
    vkCmdCopyBuffer(commands, buffer.handle(), staging.handle(), 1, &region);
    gpu.submit_and_wait(commands);
    std::memcpy(bytes.data(), staging.mapped(), bytes.size());
    return bytes;
}

}  // namespace canopy
