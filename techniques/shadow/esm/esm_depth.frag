#version 450
#extension GL_GOOGLE_include_directive : require
// exp(c z), or c z when filtering in log space (technique_params[0] = (c, log_space, ...)).
#include "moment_output.glsl"

vec4 depth_statistics(float z) {
    float c = frame.technique_params[0].x;
    bool log_space = frame.technique_params[0].y > 0.5;
    return vec4(log_space ? c * z : exp(c * z), 0.0, 0.0, 1.0);
}
