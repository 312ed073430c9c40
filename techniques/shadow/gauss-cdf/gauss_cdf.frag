#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.gauss-cdf: the depth distribution as a Gaussian of the filtered mean and variance,
// visibility biased so the mean depth is lit (Gumbau eq 7.1-7.4).
// technique_param: 0 min_variance, 1 exact erf (0/1)
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec2 moments = texture(moment_map, q.uv).rg;
    return gaussian_cdf_visibility(moments, q.receiver_depth, technique_param(0), technique_param(1) > 0.5);
}
