// The integration tests' scene, tests/data/scenes/tiny.toml: a 1 x 0.5 x 1 box (bottom at y = 1)
// floating over a 6 x 6 floor at y = 0, seen from (0, 5, 5), under one directional light.
#pragma once

#include "scene/scene.hpp"

namespace canopy::test {

Scene tiny_scene();

// The tiny scene under a square rect light of side `side` at `position`, facing straight down
// (intensity 30), so that every technique applies, area-light ones included.
Scene tiny_scene_under_rect_light(float side = 0.2f, glm::vec3 position = glm::vec3(0.0f, 4.0f, 0.0f));

// A 2 x 2-cell grass field (kind "grass", 60 blades a patch, density 0.7) on a ground plane under
// a directional sun that casts no shadows, seen from 1.2 up: the scene grass techniques render.
Scene tiny_grass_scene();

}  // namespace canopy::test
