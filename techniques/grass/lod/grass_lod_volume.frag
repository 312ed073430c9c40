#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod: the middle band's ray cast (shaders/grass_volume_fragment.glsl, drawing the band lod_band gives it).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_VOLUME
#define GRASS_LOD_VOLUME_LEVELS
#include "grass_lod_params.h"
#include "grass_volume_fragment.glsl"
