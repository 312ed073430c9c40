// C++ mirror of harness/shaders/frame_uniforms.glsl (std140). Keep both in step.
#pragma once

#include "core/param_block.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>

namespace canopy {

struct FrameUniforms {
    glm::mat4 view_proj;
    glm::mat4 view;
    glm::mat4 inverse_view_proj;
    glm::mat4 light_view;
    glm::mat4 light_proj;
    glm::vec4 camera_position;
    glm::vec4 viewport;            // width, height, vertical focal length in pixels
    glm::vec4 light_position;      // w = light type
    glm::vec4 light_axis;          // w = cos of spot half-angle
    glm::vec4 light_intensity;
    glm::vec4 light_size;
    glm::vec4 ambient;
    glm::vec4 shadow_depth_range;  // near, far, 1/(far-near), perspective?1:0
    glm::vec4 shadow_texel;        // resolution, 1/resolution, world texel size (at depth 1 if perspective)
    glm::vec4 sample_offsets[64];
    // The technique's parameter struct (ShaderParams::block); last, so its GLSL size may vary.
    alignas(16) std::array<std::byte, kMaxParamBlockBytes> technique;
};
static_assert(offsetof(FrameUniforms, technique) == 5 * 64 + 9 * 16 + 64 * 16, "must match std140 layout");
static_assert(sizeof(FrameUniforms) == 5 * 64 + 9 * 16 + 64 * 16 + kMaxParamBlockBytes, "must match std140 layout");

struct DrawConstants {
    glm::mat4 model;
    glm::vec4 normal_matrix[3];
    glm::vec4 albedo;  // rgb; w: the surface's transmission (FamilyPopulation::transmission; 0 for objects)
};
static_assert(sizeof(DrawConstants) == 128, "push constants are limited to 128 bytes");

}  // namespace canopy
