// The orthonormal frame of a rect light. Header-only and glm-only so the raster side can use
// the very same convention when it draws or samples the rectangle.
//
//   normal = normalize(direction)                      the emitting side faces `normal`
//   right  = normalize(cross(normal, rect_up_hint))    width (rect_size.x) runs along right
//   up     = cross(right, normal)                      height (rect_size.y) runs along up
//
// The rectangle is centred at `position`: points position + s * right + t * up with
// |s| <= width/2, |t| <= height/2. `up` is `rect_up_hint` made perpendicular to the normal, so a
// light facing down (-y) with the default hint +z has right = -x and up = +z.
#pragma once

#include "scene/scene.hpp"

#include <glm/glm.hpp>

namespace canopy {

struct RectLightFrame {
    glm::vec3 center{0.0f};
    glm::vec3 right{1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 size{1.0f, 1.0f};  // width along right, height along up

    glm::vec3 point(float s, float t) const { return center + s * right + t * up; }
    float area() const { return size.x * size.y; }
};

// Undefined (NaN axes) when direction is zero or parallel to rect_up_hint; the reference
// rejects such lights with a ConfigError before using the frame.
inline RectLightFrame rect_light_frame(const Light& light) {
    RectLightFrame frame;
    frame.center = light.position;
    frame.normal = glm::normalize(light.direction);
    frame.right = glm::normalize(glm::cross(frame.normal, light.rect_up_hint));
    frame.up = glm::cross(frame.right, frame.normal);
    frame.size = light.rect_size;
    return frame;
}

}  // namespace canopy
