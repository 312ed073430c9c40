#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.hard: one depth comparison against the nearest shadow-map texel (Williams 1978).
// technique_param: 0 bias_constant, 1 bias_slope
#include "forward_lighting.glsl"

float shadow_visibility(ShadowQuery q) {
    float bias = slope_scaled_bias(technique_param(0), technique_param(1), q.depth_per_texel);
    return depth_test(q.receiver_depth - bias, texelFetch(shadow_depth, nearest_texel(q.uv, textureSize(shadow_depth, 0)), 0).r);
}
