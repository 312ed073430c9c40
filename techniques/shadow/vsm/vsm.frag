#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.vsm: Chebyshev's one-tailed bound on the filtered moments (Gumbau eq 2.1-2.2).
#include "vsm_params.h"
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec2 moments = texture(moment_map, q.uv).rg;
    float p = chebyshev_upper_bound(moments, q.receiver_depth, frame.technique.min_variance);
    return reduce_light_bleeding(p, frame.technique.bleeding_reduction);
}
