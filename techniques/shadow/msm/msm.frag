#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.msm: 4 moments, Hamburger reconstruction (Peters & Klein 2015).
#include "msm_params.h"
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec4 moments = msm_decode(texture(moment_map, q.uv));
    return msm_hamburger_visibility(moments, q.receiver_depth, frame.technique.moment_bias);
}
