#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod: the near band's blades (shaders/grass_blades_vertex.glsl, drawing the band lod_band gives it).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_GEOMETRY
#include "grass_lod_params.h"
#include "grass_blades_vertex.glsl"
