#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.evsm: Chebyshev bounds on exponentially warped depths (Lauritzen & McCool 2008).
#include "evsm_params.h"
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec4 moments = texture(moment_map, q.uv);
    float p = frame.technique.components == EVSM_COMPONENTS_4
        ? evsm4_visibility(moments, q.receiver_depth, frame.technique.c_pos, frame.technique.c_neg, frame.technique.min_variance)
        : evsm2_visibility(vec2(moments.x, moments.y), q.receiver_depth, frame.technique.c_pos, frame.technique.min_variance);
    return reduce_light_bleeding(p, frame.technique.bleeding_reduction);
}
