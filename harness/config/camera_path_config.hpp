// Reads an experiment's [camera_path] table (configs/README.md, "Camera paths") into a CameraPath,
// every key and range checked with file:line errors.
#pragma once

#include "config/toml_reader.hpp"
#include "scene/camera_path.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace canopy {

// `section` is the [camera_path] table. `scenes` are the experiment's: a pose must give each of
// them a camera it can use (a viewing direction that is not along the scene camera's up).
CameraPath read_camera_path(TomlReader& section, const std::vector<Scene>& scenes);

}  // namespace canopy
