// Turns a failed Vulkan call into a GpuError that names the call and the VkResult.
#pragma once

#include "core/error.hpp"

#include <vulkan/vulkan.h>

#include <string>

namespace canopy {

const char* vk_result_name(VkResult result);

inline void vk_check(VkResult result, const char* what) {
    if (result != VK_SUCCESS) throw GpuError(std::string(what) + " failed: " + vk_result_name(result));
}

}  // namespace canopy

#define VK_CHECK(call) ::canopy::vk_check((call), #call)
