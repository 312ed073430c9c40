#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.gauss-cdf: the depth distribution as a Gaussian of the filtered mean and variance,
// visibility biased so the mean depth is lit (Gumbau eq 7.1-7.4).
#include "gauss_cdf_params.h"
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec2 moments = texture(moment_map, q.uv).rg;
    return gaussian_cdf_visibility(moments, q.receiver_depth, frame.technique.min_variance, frame.technique.exact_erf);
}
