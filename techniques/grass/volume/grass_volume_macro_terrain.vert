#version 450
#extension GL_GOOGLE_include_directive : require
// grass.volume with macro-cells on a terrain: each cuboid over its ground's height range
// (shaders/grass_volume_macro_vertex.glsl with GRASS_MACRO_TERRAIN).
#define GRASS_MACRO_TERRAIN
#include "grass_volume_params.h"
#include "grass_volume_macro_vertex.glsl"
