// The interface of a moment-map fragment shader: include this file and define
// `vec4 depth_statistics(float z)` for the normalised linear light depth z in [0, 1].
#include "frame_uniforms.glsl"

layout(location = 0) in float view_depth;
layout(location = 0) out vec4 out_statistics;

vec4 depth_statistics(float z);

void main() {
    float z = clamp((view_depth - frame.shadow_depth_range.x) * frame.shadow_depth_range.z, 0.0, 1.0);
    out_statistics = depth_statistics(z);
}
