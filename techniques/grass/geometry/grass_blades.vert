#version 450
#extension GL_GOOGLE_include_directive : require
// grass.geometry: every blade of every cell (shaders/grass_blades_vertex.glsl).
#include "grass_geometry_params.h"
#include "grass_blades_vertex.glsl"
