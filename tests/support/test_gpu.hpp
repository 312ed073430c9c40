// The Vulkan device every test in one executable shares (lavapipe unless CANOPY_TEST_DEVICE
// names another), and rendering one technique with given parameters on it.
#pragma once

#include "core/image.hpp"
#include "core/param.hpp"
#include "gpu/context.hpp"
#include "scene/scene.hpp"

#include <map>
#include <string>

namespace canopy::test {

GpuContext& gpu();

// Renders one frame of `technique` with `params` (the rest at their defaults) over `scene`, with
// a FrameRenderer of its own, on `context` (default: gpu()).
Image render_technique(const Scene& scene, const std::string& technique,
                       const std::map<std::string, ParamValue>& params, int width, int height);
Image render_technique(GpuContext& context, const Scene& scene, const std::string& technique,
                       const std::map<std::string, ParamValue>& params, int width, int height);

}  // namespace canopy::test
