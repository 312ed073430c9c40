#include "scene/scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace canopy {

float Light::size() const {
    switch (type) {
        case LightType::rect: return glm::length(rect_size);
        case LightType::sphere: return 2.0f * sphere_radius;
        default: return 0.0f;
    }
}

glm::mat4 Transform::matrix() const {
    // Scale, then rotate about X, then Y, then Z, then translate; the outer transform last.
    const glm::mat4 identity(1.0f);
    glm::mat4 local = glm::translate(identity, translate);
    local = glm::rotate(local, glm::radians(rotate_degrees.z), glm::vec3(0, 0, 1));
    local = glm::rotate(local, glm::radians(rotate_degrees.y), glm::vec3(0, 1, 0));
    local = glm::rotate(local, glm::radians(rotate_degrees.x), glm::vec3(1, 0, 0));
    local = glm::scale(local, scale);
    return outer * local;
}

const Light* Scene::shadow_light() const {
    for (const Light& light : lights)
        if (light.casts_shadows) return &light;
    return nullptr;
}

}  // namespace canopy
