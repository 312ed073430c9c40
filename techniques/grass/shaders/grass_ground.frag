#version 450
#extension GL_GOOGLE_include_directive : require
// The scene's own objects (the ground) in any grass technique's pass: the family's shading; alpha 0
// because alpha is the population's coverage (common/grass_family.hpp) and the ground is none of it.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "grass_shading.glsl"

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 0) out vec4 out_color;

void main() { out_color = grass_lit_output(draw.albedo.rgb, world_position, world_normal, 0.0, draw.albedo.w); }
