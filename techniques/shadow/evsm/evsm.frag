#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.evsm: Chebyshev bounds on exponentially warped depths (Lauritzen & McCool 2008).
// technique_param: 0 c_pos, 1 c_neg, 2 components (2 or 4), 3 min_variance, 4 bleeding_reduction
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec4 moments = texture(moment_map, q.uv);
    float p = technique_param(2) > 3.0
        ? evsm4_visibility(moments, q.receiver_depth, technique_param(0), technique_param(1), technique_param(3))
        : evsm2_visibility(vec2(moments.x, moments.y), q.receiver_depth, technique_param(0), technique_param(3));
    return reduce_light_bleeding(p, technique_param(4));
}
