#version 450
#extension GL_GOOGLE_include_directive : require
// grass.slices: each cell's vertical and horizontal quads (shaders/grass_slices_vertex.glsl).
#include "grass_slices_params.h"
#include "grass_slices_vertex.glsl"
