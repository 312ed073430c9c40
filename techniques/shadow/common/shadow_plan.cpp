#include "shadow_plan.hpp"

namespace canopy {

const char* to_string(DepthFormat format) { return format == DepthFormat::d16 ? "d16" : "d32f"; }

const char* to_string(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return "r16f";
        case MomentFormat::r32f: return "r32f";
        case MomentFormat::rg16f: return "rg16f";
        case MomentFormat::rg32f: return "rg32f";
        case MomentFormat::rgba16f: return "rgba16f";
        case MomentFormat::rgba32f: return "rgba32f";
        case MomentFormat::rgba16unorm: return "rgba16unorm";
    }
    return "?";
}

uint32_t bytes_per_texel(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return 2;
        case MomentFormat::r32f: return 4;
        case MomentFormat::rg16f: return 4;
        case MomentFormat::rg32f: return 8;
        case MomentFormat::rgba16f: return 8;
        case MomentFormat::rgba32f: return 16;
        case MomentFormat::rgba16unorm: return 8;
    }
    return 0;
}

VkFormat vk_format(DepthFormat format) {
    return format == DepthFormat::d16 ? VK_FORMAT_D16_UNORM : VK_FORMAT_D32_SFLOAT;
}

VkFormat vk_format(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return VK_FORMAT_R16_SFLOAT;
        case MomentFormat::r32f: return VK_FORMAT_R32_SFLOAT;
        case MomentFormat::rg16f: return VK_FORMAT_R16G16_SFLOAT;
        case MomentFormat::rg32f: return VK_FORMAT_R32G32_SFLOAT;
        case MomentFormat::rgba16f: return VK_FORMAT_R16G16B16A16_SFLOAT;
        case MomentFormat::rgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
        case MomentFormat::rgba16unorm: return VK_FORMAT_R16G16B16A16_UNORM;
    }
    return VK_FORMAT_UNDEFINED;
}

}  // namespace canopy
