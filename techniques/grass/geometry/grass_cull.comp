#version 450
#extension GL_GOOGLE_include_directive : require
// grass.geometry's cull (culling = "gpu"): the copies within max_distance (0: any) whose box may be
// seen (shaders/grass_cull.glsl).
#include "grass_geometry_params.h"
#define FRAME_BINDING 0
#include "frame_uniforms.glsl"
#define GRASS_CULL_MAX_DISTANCE frame.technique.max_distance
#include "grass_cull.glsl"
