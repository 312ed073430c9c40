#version 450
#extension GL_GOOGLE_include_directive : require
// (z, z, z): the seeds of the min / max / mean prefilter (min_max_mean_filter.comp).
#include "moment_output.glsl"

vec4 depth_statistics(float z) { return vec4(z, z, z, 1.0); }
