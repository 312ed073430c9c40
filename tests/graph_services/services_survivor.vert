#version 450
#extension GL_GOOGLE_include_directive : require
// The culled quads' vertices: xy in pixels, z the quad's tag (its index + 1).
#include "frame_uniforms.glsl"

layout(location = 0) in vec4 vertex;
layout(location = 0) flat out float tag;

void main() {
    gl_Position = vec4(vertex.xy / frame.viewport.xy * 2.0 - 1.0, 0.5, 1.0);
    tag = vertex.z;
}
