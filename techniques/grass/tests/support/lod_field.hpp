// The field grass.lod's tests draw: 3 x 3 cells of 60 wide blades on a ground plane, seen from a
// low, standing eye, so its cells lie 1 to 5 m away, in all three bands with bands that short.
#pragma once

#include "scene/scene.hpp"

#include <string>

namespace canopy::grass::test {

// `more`: TOML appended to the scene (another [[population]], say).
Scene lod_field_scene(const std::string& more = "");

}  // namespace canopy::grass::test
