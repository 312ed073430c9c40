#version 450
#extension GL_GOOGLE_include_directive : require
// Four power moments of depth, in Peters & Klein's quantisation-friendly basis.
#include "moment_output.glsl"
#include "shadow_filtering.h"

vec4 depth_statistics(float z) { return msm_encode(z); }
