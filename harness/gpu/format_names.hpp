// The short names canopy uses for Vulkan formats in messages and graph descriptions ("d32f",
// "rgba16f"), the same words technique parameters use.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace canopy {

// "VkFormat <n>" for a format canopy has no name for.
std::string format_name(VkFormat format);

}  // namespace canopy
