#include "scene/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace canopy {

glm::mat4 view_matrix(const Camera& camera) {
    return glm::lookAt(camera.position, camera.target, camera.up);
}

glm::mat4 projection_matrix(const Camera& camera, float aspect) {
    glm::mat4 proj = glm::perspective(glm::radians(camera.fov_y_degrees), aspect, camera.near_plane,
                                      camera.far_plane);
    proj[1][1] *= -1.0f;  // Vulkan's framebuffer y points down: keep row 0 at the top.
    return proj;
}

glm::mat4 view_projection(const Camera& camera, uint32_t width, uint32_t height) {
    return projection_matrix(camera, float(width) / float(height)) * view_matrix(camera);
}

Ray primary_ray(const Camera& camera, int width, int height, float px, float py) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
    const float aspect = float(width) / float(height);
    const float ndc_x = 2.0f * px / float(width) - 1.0f;
    const float ndc_y = 1.0f - 2.0f * py / float(height);
    const glm::vec3 dir = forward + right * (ndc_x * tan_half * aspect) + up * (ndc_y * tan_half);
    return {camera.position, glm::normalize(dir)};
}

glm::vec2 project_to_pixel(const Camera& camera, int width, int height, const glm::vec3& p) {
    const glm::vec4 clip = view_projection(camera, uint32_t(width), uint32_t(height)) * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * float(width), (ndc.y * 0.5f + 0.5f) * float(height)};
}

}  // namespace canopy
