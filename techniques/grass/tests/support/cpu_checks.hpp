// What the grass tests compute on the CPU themselves, apart from the shaders' headers: how far two
// images differ, and whether a box may be seen (the clip-space definition, written once here).
#pragma once

#include "core/image.hpp"

#include <glm/glm.hpp>

#include <array>

namespace canopy::grass::test {

// The largest difference of any channel of any pixel (the images must have the same size).
float max_difference(const Image& a, const Image& b);

// False only when all 8 corners (world) lie beyond one of the clip planes of `view_proj` (world ->
// clip, depth 0 to 1): a box across a frustum corner counts as seen.
bool corners_may_be_seen(const glm::mat4& view_proj, const std::array<glm::vec3, 8>& corners);

}  // namespace canopy::grass::test
