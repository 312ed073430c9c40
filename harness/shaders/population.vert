#version 450
#extension GL_GOOGLE_include_directive : require
// Camera-space transform of a population's copies (PassContext::draw_population): scene.vert
// with the copy's matrices read per instance (VertexLayout::population) instead of pushed per
// draw, so one draw places every copy. Outputs 0-1 are scene.vert's, for the same fragment
// shaders; 2-3 carry the prototype-space position and the population's alpha mask to fragment
// shaders that include population_alpha.glsl.
#include "frame_uniforms.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in mat4 instance_model;          // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8
layout(location = 9) in vec4 instance_alpha_mask;         // alpha_mask.h

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;
layout(location = 2) out vec3 local_position;
layout(location = 3) flat out vec4 alpha_mask;

void main() {
    vec4 world = instance_model * vec4(in_position, 1.0);
    world_position = world.xyz;
    mat3 normal_matrix = mat3(instance_normal_matrix[0].xyz, instance_normal_matrix[1].xyz,
                              instance_normal_matrix[2].xyz);
    world_normal = normal_matrix * in_normal;
    local_position = in_position;
    alpha_mask = instance_alpha_mask;
    gl_Position = frame.view_proj * world;
}
