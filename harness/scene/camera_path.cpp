#include "scene/camera_path.hpp"

#include <algorithm>
#include <cmath>

namespace canopy {

Camera CameraPath::at(const Camera& base, int frame) const {
    Camera camera = base;
    if (poses.empty() || frames <= 0) return camera;
    const auto fov = [&](const CameraPose& p) { return p.fov_y_degrees > 0.0f ? p.fov_y_degrees : base.fov_y_degrees; };
    const int f = ((frame % frames) + frames) % frames;
    // Pose i sits at frame i * (frames - 1) / (poses - 1); between two, t runs linearly from 0 to 1.
    const double along = poses.size() == 1 || frames == 1 ? 0.0 : double(f) * double(poses.size() - 1) / double(frames - 1);
    const size_t i = std::min(size_t(along), poses.size() - 1);
    const size_t j = std::min(i + 1, poses.size() - 1);
    const float t = float(along - double(i));
    camera.position = glm::mix(poses[i].position, poses[j].position, t);
    camera.target = glm::mix(poses[i].target, poses[j].target, t);
    camera.fov_y_degrees = fov(poses[i]) + t * (fov(poses[j]) - fov(poses[i]));
    return camera;
}

}  // namespace canopy
