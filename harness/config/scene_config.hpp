// Loads a scene description (configs/README.md documents the format) into a Scene, checking
// every key, type and range so that mistakes surface as file:line errors before anything runs.
#pragma once

#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace canopy {

// Throws ConfigError for a missing file, malformed TOML, unknown keys or invalid values.
Scene load_scene(const std::filesystem::path& file);

// The same from TOML text; `file` names it in errors and anchors relative mesh paths.
Scene parse_scene(const std::string& text, const std::filesystem::path& file);

class TomlReader;
// A [camera] table's keys (position, target, up, fov, near, far) over `camera`, each checked as a
// scene's are; keys not given keep their value. The caller finishes the reader (unknown keys).
void read_scene_camera(TomlReader& reader, Camera& camera);

// A direction read as given and normalised in double precision (a float length of huge
// components would overflow); an error naming `key`'s line when it is (nearly) the zero vector.
glm::vec3 read_direction(TomlReader& reader, std::string_view key, const glm::vec3& fallback,
                         const std::string& zero_message, const std::string& zero_hint);

}  // namespace canopy
