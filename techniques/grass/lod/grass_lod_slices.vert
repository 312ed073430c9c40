#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod with middle = "slices": the middle band's BTF slices (shaders/grass_slices_vertex.glsl, drawing the band lod_band gives it).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_VOLUME
#include "grass_lod_params.h"
#include "grass_slices_vertex.glsl"
