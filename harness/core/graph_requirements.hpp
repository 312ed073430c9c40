// What a FrameGraph asks of the scene and the device, in words, for `canopy list`. The checks
// themselves are check_supported (render/frame_renderer.hpp), run before anything is written.
#pragma once

#include "graph/frame_graph.hpp"

#include <string>
#include <vector>

namespace canopy {

// e.g. {"an area light (rect or sphere)", "depth-compare sampling of d32f"}; a graph with a light
// view always needs a shadow-casting light.
std::vector<std::string> graph_requirements(const FrameGraph& graph);

}  // namespace canopy
