#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.power-cdf: the depth CDF reconstructed as t^beta from the filtered minimum, maximum
// and mean (Gumbau eq 7.5-7.7). The receiver depth is reduced by the storage format's rounding
// error (technique_param 0: relative, 2 ulp), so a planar receiver whose stored min, max and
// mean were rounded below its exact depth stays lit, as eq 7.1 requires.
#include "forward_lighting.glsl"
#include "shadow_filtering.h"

float shadow_visibility(ShadowQuery q) {
    vec3 s = texture(moment_map, q.uv).rgb;  // (z_min, z_max, mean)
    float receiver = q.receiver_depth * (1.0 - technique_param(0));
    return power_cdf_visibility(s.r, s.g, s.b, receiver);
}
