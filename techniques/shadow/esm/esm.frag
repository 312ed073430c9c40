#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.esm: visibility = exp(c (z_occluder - z_receiver)) from the prefiltered exp(c z).
// technique_param: 0 exponent c, 1 log-space (0/1)
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    float stored = texture(moment_map, q.uv).r;
    float c = technique_param(0);
    return technique_param(1) > 0.5 ? esm_visibility_log(stored, q.receiver_depth, c)
                                    : esm_visibility(stored, q.receiver_depth, c);
}
