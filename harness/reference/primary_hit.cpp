#include "reference/primary_hit.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace canopy {

void check_camera_representable(const Scene& scene) {
    const Camera& camera = scene.camera;
    const auto reject = [&](const std::string& message) {
        throw ConfigError(scene.file, 0,
                          fmt::format("the reference renderer cannot use the camera of scene '{}': {}", scene.name,
                                      message));
    };
    const glm::vec3 view = camera.target - camera.position;
    if (!(glm::length(view) > 0.0f) || !std::isfinite(glm::length(view))) reject("its position equals its target");
    const glm::vec3 right = glm::cross(view, camera.up);
    if (!(glm::length(right) > 1e-6f * glm::length(view) * glm::length(camera.up)))
        reject("its up vector is zero or parallel to the view direction");
    if (!(camera.fov_y_degrees > 0.0f && camera.fov_y_degrees < 180.0f))
        reject(fmt::format("its vertical field of view {} is outside (0, 180) degrees", camera.fov_y_degrees));
    if (!(camera.near_plane >= 0.0f && camera.far_plane > camera.near_plane))
        reject(fmt::format("its near and far planes ({}, {}) do not bound a depth range", camera.near_plane,
                           camera.far_plane));
}

}  // namespace canopy
