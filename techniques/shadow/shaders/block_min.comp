#version 450
#extension GL_GOOGLE_include_directive : require
// Coarse map (Gumbau 2011, 6.2.1): each output texel is the minimum (nearest the light) of the
// downsample x downsample block of the shadow map it covers. A partial block at the map's edge
// (a size not divisible by the block) reads its last texels again (fetch_block clamps): the
// minimum is that of the texels it covers.
#include "separable_filter.glsl"

vec4 filter_texel(ivec2 xy) {
    float lowest = 1.0;
    for (int dy = 0; dy < filter_pass.downsample; ++dy)
        for (int dx = 0; dx < filter_pass.downsample; ++dx) lowest = min(lowest, fetch_block(xy, dx, dy).r);
    return vec4(lowest, 0.0, 0.0, 1.0);
}
