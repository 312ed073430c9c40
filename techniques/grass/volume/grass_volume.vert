#version 450
#extension GL_GOOGLE_include_directive : require
// grass.volume: each cell's carrier cuboid (shaders/grass_volume_vertex.glsl).
#include "grass_volume_params.h"
#include "grass_volume_vertex.glsl"
