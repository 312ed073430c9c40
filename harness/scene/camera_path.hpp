// A camera that moves: key poses spread evenly over the frames of one traversal, interpolated
// linearly between neighbours, so LoD changes and popping can be measured frame by frame
// (experiment config [camera_path]). Pure data and math, no Vulkan.
#pragma once

#include "scene/scene.hpp"

#include <vector>

namespace canopy {

struct CameraPose {
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f};
    float fov_y_degrees = 0.0f;  // 0: the scene camera's
};

struct CameraPath {
    int frames = 0;                 // frames of one traversal; one timing sample renders them all
    std::vector<CameraPose> poses;  // at least two: the first at frame 0, the last at frame frames - 1
    // After the measurement each case renders one more traversal (untimed) and the reference is
    // ray-traced at every frame of it: the popping metrics (metrics/popping.hpp).
    bool popping = false;

    // The camera of traversal frame `frame` (taken modulo `frames`): `base` (the scene's camera:
    // its up vector and clip planes) with the interpolated position, target and field of view.
    Camera at(const Camera& base, int frame) const;
};

}  // namespace canopy
