#version 450
#extension GL_GOOGLE_include_directive : require
// grass.image: one horizontal quad per cell a little above the ground (Lemme §5.3, L611),
// placed and mirrored with the cell (PassContext::draw_over_population).
#include "grass_image_params.h"
#include "frame_uniforms.glsl"

layout(location = 0) in vec4 quad_position;             // patch space
layout(location = 1) in vec4 quad_uv;
layout(location = 2) in mat4 instance_model;             // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8
layout(location = 9) in vec4 corner_densities;           // patch order (grass_density.h)

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec2 uv;
layout(location = 2) out vec2 patch_xz;
layout(location = 3) flat out vec4 densities;
layout(location = 4) flat out vec3 normal_matrix[3];  // locations 4-6

void main() {
    vec4 world = instance_model * vec4(quad_position.xyz, 1.0);
    world_position = world.xyz;
    uv = quad_uv.xy;
    patch_xz = quad_position.xz;
    densities = corner_densities;
    for (int c = 0; c < 3; ++c) normal_matrix[c] = instance_normal_matrix[c].xyz;
    gl_Position = frame.view_proj * world;
}
