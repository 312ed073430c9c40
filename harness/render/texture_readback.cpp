#include "render/texture_readback.hpp"

#include <cstring>
#include <stdexcept>
#include <vector>

namespace canopy {

Image read_texture(const GpuContext& gpu, const Texture& texture, VkImageLayout layout) {
    const VkFormat format = texture.format();
    if (format != VK_FORMAT_R32_SFLOAT && format != VK_FORMAT_R32G32B32A32_SFLOAT)
        throw std::invalid_argument("read_texture: only R32_SFLOAT and R32G32B32A32_SFLOAT textures");
    const size_t channels = format == VK_FORMAT_R32_SFLOAT ? 1 : 4;
    const size_t texels = size_t(texture.width()) * texture.height();
    MemoryLedger ledger;  // transient, not charged to anyone
    Buffer staging(gpu, ledger, "readback", texels * channels * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    VkCommandBuffer commands = gpu.begin_commands();
    transition(commands, texture, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {texture.width(), texture.height(), 1};
    vkCmdCopyImageToBuffer(commands, texture.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    transition(commands, texture, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
    gpu.submit_and_wait(commands);

    Image image(int(texture.width()), int(texture.height()));
    const float* source = static_cast<const float*>(staging.mapped());
    if (channels == 4) {
        std::memcpy(image.pixels.data(), source, texels * 4 * sizeof(float));
    } else {
        for (size_t i = 0; i < texels; ++i) {
            image.pixels[4 * i] = source[i];
            image.pixels[4 * i + 3] = 1.0f;
        }
    }
    return image;
}

}  // namespace canopy
