// The Vulkan device every test in one executable shares (lavapipe unless CANOPY_TEST_DEVICE
// names another), and rendering one technique with given parameters on it.
#pragma once

#include "core/image.hpp"
#include "core/param.hpp"
#include "core/technique.hpp"
#include "gpu/context.hpp"
#include "scene/scene.hpp"

#include <map>
#include <string>

namespace canopy::test {

// The device selector tests use: CANOPY_TEST_DEVICE, or "" (lavapipe).
std::string device_selector();

GpuContext& gpu();

// The frame graph of registered `technique` with `params`, the rest at their defaults.
FrameGraph technique_graph(const std::string& technique, const std::map<std::string, ParamValue>& params = {});

// Renders one frame of `technique` with `params` (the rest at their defaults) over `scene`, with
// a FrameRenderer of its own, on `context` (default: gpu()).
Image render_technique(const Scene& scene, const std::string& technique,
                       const std::map<std::string, ParamValue>& params, int width, int height);
Image render_technique(GpuContext& context, const Scene& scene, const std::string& technique,
                       const std::map<std::string, ParamValue>& params, int width, int height);

}  // namespace canopy::test
