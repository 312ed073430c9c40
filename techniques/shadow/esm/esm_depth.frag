#version 450
#extension GL_GOOGLE_include_directive : require
// exp(c z), or c z when filtering in log space (frame.technique: exponent, log_space).
#include "esm_params.h"
#include "moment_output.glsl"

vec4 depth_statistics(float z) {
    float c = frame.technique.exponent;
    bool log_space = frame.technique.log_space;
    return vec4(log_space ? c * z : exp(c * z), 0.0, 0.0, 1.0);
}
