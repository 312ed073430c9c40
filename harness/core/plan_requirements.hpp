// What a FramePlan asks of the scene and the device, in words, for `canopy list`. The checks
// themselves are check_supported (render/frame_renderer.hpp), run before anything is written.
#pragma once

#include "core/technique.hpp"

#include <string>
#include <vector>

namespace canopy {

// e.g. {"an area light (rect or sphere)", "depth-compare sampling of d32f"}; a plan with a
// shadow or moment map always needs a shadow-casting light.
std::vector<std::string> plan_requirements(const FramePlan& plan);

}  // namespace canopy
