#include "render/light_view.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace canopy {

namespace {

constexpr float kMaxHalfAngleTan = 5.67f;  // tan(80 degrees): wider maps waste all their texels

glm::mat4 look_along(const glm::vec3& eye, const glm::vec3& axis) {
    glm::vec3 up = std::abs(axis.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAt(eye, eye + axis, up);
}

std::array<glm::vec3, 8> corners(const Bounds& b) {
    std::array<glm::vec3, 8> c;
    for (int i = 0; i < 8; ++i)
        c[size_t(i)] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
    return c;
}

}  // namespace

LightView compute_light_view(const Light& light, const Bounds& scene_bounds, uint32_t resolution) {
    // An empty scene casts no shadow; any small box keeps the fit below finite.
    Bounds bounds = scene_bounds;
    if (bounds.empty()) bounds.extend(glm::vec3(0.0f));
    LightView lv;
    const float radius = std::max(bounds.radius(), 1e-3f);
    const glm::vec3 center = bounds.center();

    if (light.type == LightType::directional) {
        const glm::vec3 axis = glm::normalize(light.direction);
        const glm::vec3 eye = center - axis * (2.0f * radius);
        lv.view = look_along(eye, axis);
        lv.near_plane = radius;
        lv.far_plane = 3.0f * radius;
        lv.perspective = false;
        lv.projection = glm::ortho(-radius, radius, -radius, radius, lv.near_plane, lv.far_plane);
        lv.texel_world = 2.0f * radius / float(resolution);
    } else {
        glm::vec3 axis = light.direction;
        if (light.type == LightType::sphere) {
            axis = center - light.position;
            if (glm::length(axis) < 1e-6f) axis = glm::vec3(0.0f, -1.0f, 0.0f);
        }
        axis = glm::normalize(axis);
        lv.view = look_along(light.position, axis);

        // Fit depth range and field of view to the scene's bounding box seen from the light.
        float nearest = 1e30f, farthest = 0.0f, max_tan = 0.0f;
        bool behind = false;
        for (const glm::vec3& c : corners(bounds)) {
            glm::vec3 v = glm::vec3(lv.view * glm::vec4(c, 1.0f));
            float depth = -v.z;
            farthest = std::max(farthest, depth);
            if (depth <= 1e-4f * radius) { behind = true; continue; }
            nearest = std::min(nearest, depth);
            max_tan = std::max({max_tan, std::abs(v.x) / depth, std::abs(v.y) / depth});
        }
        lv.far_plane = std::max(farthest, 1e-3f) * 1.01f;
        lv.near_plane = behind ? lv.far_plane * 1e-3f : std::max(nearest * 0.99f, lv.far_plane * 1e-3f);
        float half_tan = behind ? kMaxHalfAngleTan : std::min(max_tan * 1.01f, kMaxHalfAngleTan);
        if (light.type == LightType::spot)
            half_tan = std::min(std::tan(glm::radians(std::min(light.spot_angle_degrees, 80.0f))), kMaxHalfAngleTan);
        lv.perspective = true;
        lv.projection = glm::perspective(2.0f * std::atan(half_tan), 1.0f, lv.near_plane, lv.far_plane);
        lv.texel_world = 2.0f * half_tan / float(resolution);
    }
    return lv;
}

}  // namespace canopy
