#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod under culling = "quadtree" on a terrain: the middle band's ray walk shifted by the ground (shaders/grass_volume_macro_fragment.glsl).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_VOLUME
#define GRASS_LOD_VOLUME_LEVELS
#define GRASS_MACRO_TERRAIN
#include "grass_lod_params.h"
#include "grass_volume_macro_fragment.glsl"
