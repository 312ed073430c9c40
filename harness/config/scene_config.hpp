// Loads a scene description (configs/README.md documents the format) into a Scene, checking
// every key, type and range so that mistakes surface as file:line errors before anything runs.
#pragma once

#include "scene/scene.hpp"

#include <filesystem>
#include <string>

namespace canopy {

// Throws ConfigError for a missing file, malformed TOML, unknown keys or invalid values.
Scene load_scene(const std::filesystem::path& file);

// The same from TOML text; `file` names it in errors and anchors relative mesh paths.
Scene parse_scene(const std::string& text, const std::filesystem::path& file);

class TomlReader;
// A [camera] table's keys (position, target, up, fov, near, far) over `camera`, each checked as a
// scene's are; keys not given keep their value. The caller finishes the reader (unknown keys).
void read_scene_camera(TomlReader& reader, Camera& camera);

}  // namespace canopy
