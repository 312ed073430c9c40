#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.hard: one depth comparison against the nearest shadow-map texel (Williams 1978).
#include "hard_params.h"
#include "forward_lighting.glsl"

float shadow_visibility(ShadowQuery q) {
    float bias = slope_scaled_bias(frame.technique.bias_constant, frame.technique.bias_slope, q.depth_per_texel);
    return depth_test(q.receiver_depth - bias, texelFetch(shadow_depth, nearest_texel(q.uv, textureSize(shadow_depth, 0)), 0).r);
}
