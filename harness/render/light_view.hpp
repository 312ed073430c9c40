// How the shadow light sees the scene: the view and projection of its shadow map.
#pragma once

#include "scene/geometry.hpp"

namespace canopy {

struct LightView {
    glm::mat4 view{1.0f};        // world -> light view (looking down -z)
    glm::mat4 projection{1.0f};  // Vulkan clip space, row 0 of the map at v = 0
    float near_plane = 0.1f;
    float far_plane = 10.0f;
    bool perspective = true;
    // World size of one shadow texel: at view depth 1 for perspective lights, absolute for
    // orthographic ones.
    float texel_world = 0.0f;
};

// Directional lights get an orthographic map around the scene's bounding sphere; spot lights
// a perspective map over their cone; rect and sphere lights a perspective map from their
// centre, along the rect's normal (or towards the scene for spheres), fitted to the scene's
// bounds. Depth range always covers the whole scene.
LightView compute_light_view(const Light& light, const Bounds& scene_bounds, uint32_t resolution);

}  // namespace canopy
