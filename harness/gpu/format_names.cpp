#include "gpu/format_names.hpp"

#include <fmt/format.h>

namespace canopy {

std::string format_name(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM: return "d16";
        case VK_FORMAT_D32_SFLOAT: return "d32f";
        case VK_FORMAT_R16_SFLOAT: return "r16f";
        case VK_FORMAT_R32_SFLOAT: return "r32f";
        case VK_FORMAT_R16G16_SFLOAT: return "rg16f";
        case VK_FORMAT_R32G32_SFLOAT: return "rg32f";
        case VK_FORMAT_R16G16B16A16_SFLOAT: return "rgba16f";
        case VK_FORMAT_R32G32B32A32_SFLOAT: return "rgba32f";
        case VK_FORMAT_R16G16B16A16_UNORM: return "rgba16unorm";
        case VK_FORMAT_R8G8B8A8_UNORM: return "rgba8";
        default: return fmt::format("VkFormat {}", int(format));
    }
}

}  // namespace canopy
