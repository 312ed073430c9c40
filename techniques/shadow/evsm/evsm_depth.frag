#version 450
#extension GL_GOOGLE_include_directive : require
// EVSM moments of the warped depth: (p, p^2, n, n^2) (frame.technique: c_pos, c_neg).
#include "evsm_params.h"
#include "moment_output.glsl"
#include "shadow_filtering.h"

vec4 depth_statistics(float z) {
    return evsm_moments(z, frame.technique.c_pos, frame.technique.c_neg);
}
