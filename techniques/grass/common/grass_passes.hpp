// What every grass technique's frame graph declares alike: resource uses written briefly, and
// the pipeline that draws the scene's own objects (the ground) with the family's shading.
#pragma once

#include "graph/frame_graph.hpp"
#include "graph/raster_state.hpp"

#include <array>
#include <string>

namespace canopy::grass {

inline ResourceUse use(const std::string& resource, Use how, int binding = -1) { return {resource, how, binding}; }

// An attachment cleared at the pass's start; `layer`: one layer of a layered image (else all).
inline ResourceUse cleared(const std::string& image, Use how, std::array<float, 4> clear, bool store = true,
                           uint32_t layer = ~0u) {
    ResourceUse u{image, how};
    u.clear = clear;
    u.store = store;
    if (layer != ~0u) u.range = Subresource{0, ~0u, layer, 1};
    return u;
}

inline constexpr std::array<float, 4> kFarDepth{1.0f, 0.0f, 0.0f, 0.0f};

// scene.vert and grass_ground.frag: the scene's objects shaded as the blades are.
RasterState ground_state();

}  // namespace canopy::grass
