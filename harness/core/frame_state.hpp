// What a renderer is given every frame: which frame of the run it is and where the camera is.
// Pure data, no Vulkan.
#pragma once

#include "scene/scene.hpp"

#include <cstdint>

namespace canopy {

struct FrameState {
    uint32_t frame_index = 0;
    Camera camera;
};

}  // namespace canopy
