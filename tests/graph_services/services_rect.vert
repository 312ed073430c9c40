#version 450
#extension GL_GOOGLE_include_directive : require
// Instanced screen-space rectangles: a unit-square corner per vertex, a pixel rectangle
// (x0, y0, x1, y1) and an RGBA colour per instance. The target is the camera target's size.
#include "frame_uniforms.glsl"

layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 rect;
layout(location = 2) in vec4 color;
layout(location = 0) flat out vec4 rect_color;

void main() {
    const vec2 pixel = mix(rect.xy, rect.zw, corner);
    gl_Position = vec4(pixel / frame.viewport.xy * 2.0 - 1.0, 0.5, 1.0);
    rect_color = color;
}
