#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod under culling = "quadtree": the middle band's macro-cell ray walk (shaders/grass_volume_macro_fragment.glsl, drawing each cell's band).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_VOLUME
#define GRASS_LOD_VOLUME_LEVELS
#include "grass_lod_params.h"
#include "grass_volume_macro_fragment.glsl"
