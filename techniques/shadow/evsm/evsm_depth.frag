#version 450
#extension GL_GOOGLE_include_directive : require
// EVSM moments of the warped depth: (p, p^2, n, n^2) (technique_params[0] = (c_pos, c_neg, ...)).
#include "moment_output.glsl"
#include "shadow_filtering.h"

vec4 depth_statistics(float z) {
    return evsm_moments(z, frame.technique_params[0].x, frame.technique_params[0].y);
}
