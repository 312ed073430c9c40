// The one camera convention shared by the rasteriser and the ray tracer, so both see the same
// pixels: image row 0 is the top; pixel (x, y) covers [x, x+1) x [y, y+1) in pixel units.
#pragma once

#include "scene/scene.hpp"

namespace canopy {

glm::mat4 view_matrix(const Camera& camera);
// Vulkan clip space (depth 0..1, y pointing down the image), so rasterised row 0 is the top.
glm::mat4 projection_matrix(const Camera& camera, float aspect);
// World -> clip for an image of `width` x `height`: the frame uniforms' view_proj, which CPU
// passes that cull for the GPU must match exactly.
glm::mat4 view_projection(const Camera& camera, uint32_t width, uint32_t height);

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit length
};

// The ray through image position (px, py) in pixel units (px = x + 0.5 is the centre of column x).
Ray primary_ray(const Camera& camera, int width, int height, float px, float py);

// Where world point `p` lands in the image, in pixel units (inverse of primary_ray).
glm::vec2 project_to_pixel(const Camera& camera, int width, int height, const glm::vec3& p);

}  // namespace canopy
