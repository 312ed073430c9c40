#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.vsm: Chebyshev's one-tailed bound on the filtered moments (Gumbau eq 2.1-2.2).
// technique_param: 0 min_variance, 1 bleeding_reduction
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec2 moments = texture(moment_map, q.uv).rg;
    float p = chebyshev_upper_bound(moments, q.receiver_depth, technique_param(0));
    return reduce_light_bleeding(p, technique_param(1));
}
