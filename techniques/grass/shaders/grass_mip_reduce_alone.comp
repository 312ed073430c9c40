#version 450
#extension GL_GOOGLE_include_directive : require
// grass_mip_reduce.glsl for a colour without a companion (a billboard's baked radiance).
#include "grass_mip_reduce.glsl"
