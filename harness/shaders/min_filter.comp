#version 450
#extension GL_GOOGLE_include_directive : require
// Minimum of 2r+1 texels (channel r): separable, so two passes give the (2r+1)^2 minimum.
// Dilates shadow casters towards the light for screen-space soft shadows (Gumbau 6.2.1).
#include "separable_filter.glsl"

vec4 filter_texel(ivec2 xy) {
    float lowest = fetch(xy, 0).r;
    for (int i = -filter_pass.radius; i <= filter_pass.radius; ++i) lowest = min(lowest, fetch(xy, i).r);
    return vec4(lowest, 0.0, 0.0, 1.0);
}
