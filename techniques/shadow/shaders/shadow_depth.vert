#version 450
#extension GL_GOOGLE_include_directive : require
// Shadow-map pass: geometry seen from the shadow light.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;

layout(location = 0) out float view_depth;

void main() {
    vec4 light_space = frame.light_view * (draw.model * vec4(in_position, 1.0));
    view_depth = -light_space.z;
    gl_Position = frame.light_proj * light_space;
}
