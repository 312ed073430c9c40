// Dynamic-rendering boilerplate shared by every raster pass: attachments, viewport, scissor;
// and the samplers passes read their inputs with.
#pragma once

#include "gpu/context.hpp"

#include <span>

namespace canopy {

struct ColorTarget {
    VkImageView view = VK_NULL_HANDLE;
    VkClearColorValue clear{};
};

struct DepthTarget {
    VkImageView view = VK_NULL_HANDLE;
    bool store = false;  // keep the depth (a shadow map) or discard it (a z-buffer)
};

// Begins rendering a width x height area into the cleared targets (images already in
// COLOR_ATTACHMENT_OPTIMAL / DEPTH_ATTACHMENT_OPTIMAL, depth cleared to 1) and sets the
// viewport and scissor to that area.
void begin_rendering(VkCommandBuffer commands, uint32_t width, uint32_t height, std::span<const ColorTarget> colors,
                     const DepthTarget& depth);

// Clamp-to-edge samplers: NEAREST or LINEAR, optionally depth-compare (LESS_OR_EQUAL: a
// reference at or in front of the stored depth is lit).
VkSampler create_sampler(VkDevice device, VkFilter filter, bool compare = false);

}  // namespace canopy
