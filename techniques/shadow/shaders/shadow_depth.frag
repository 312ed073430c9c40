#version 450
#extension GL_GOOGLE_include_directive : require
// Stores linear light-space depth normalised to [near, far], identical for perspective and
// orthographic lights, so every technique compares depths in the same units.
#include "frame_uniforms.glsl"

layout(location = 0) in float view_depth;

void main() {
    gl_FragDepth = clamp((view_depth - frame.shadow_depth_range.x) * frame.shadow_depth_range.z, 0.0, 1.0);
}
