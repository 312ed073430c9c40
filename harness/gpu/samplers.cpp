#include "gpu/samplers.hpp"

namespace canopy {

VkSampler create_sampler(VkDevice device, VkFilter filter, bool compare) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.compareEnable = compare ? VK_TRUE : VK_FALSE;
    info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    info.maxLod = 0.0f;
    VkSampler sampler;
    VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
    return sampler;
}

}  // namespace canopy
