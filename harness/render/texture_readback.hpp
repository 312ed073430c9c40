// Reading a float texture back to the host, for tests and debugging views of intermediate
// buffers (the coarse map, the screen-space shadow buffer).
#pragma once

#include "core/image.hpp"
#include "gpu/resources.hpp"

namespace canopy {

// The texels of `texture` (R32_SFLOAT into the red channel, with alpha 1, or R32G32B32A32_SFLOAT;
// created with TRANSFER_SRC usage), which is in `layout` and is left in it.
Image read_texture(const GpuContext& gpu, const Texture& texture, VkImageLayout layout);

}  // namespace canopy
