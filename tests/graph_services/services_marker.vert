#version 450
#extension GL_GOOGLE_include_directive : require
// A world-space triangle seen through the frame's camera (frame.view_proj).
#include "frame_uniforms.glsl"

layout(location = 0) in vec3 position;

void main() { gl_Position = frame.view_proj * vec4(position, 1.0); }
