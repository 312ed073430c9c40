// How the scene's shadow-casting light sees it: a view and projection fitted to the scene. A
// service any family may declare (GraphNeeds::light_view_resolution) for passes that render
// from the light: the shadow family's maps today; a grass or foliage technique that casts
// shadows, or slices baked under the sun, would declare it the same way.
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
