#version 450
#extension GL_GOOGLE_include_directive : require
// Camera-space transform of scene geometry for the lit pass.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;

void main() {
    vec4 world = draw.model * vec4(in_position, 1.0);
    world_position = world.xyz;
    mat3 normal_matrix = mat3(draw.normal_matrix[0].xyz, draw.normal_matrix[1].xyz, draw.normal_matrix[2].xyz);
    world_normal = normal_matrix * in_normal;
    gl_Position = frame.view_proj * world;
}
