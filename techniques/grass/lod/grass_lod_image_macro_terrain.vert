#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod under culling = "quadtree" on a terrain: the far band's macro-cell quads lifted onto the grid heights (shaders/grass_image_macro_vertex.glsl).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_IMAGE
#define GRASS_MACRO_TERRAIN
#include "grass_lod_params.h"
#include "grass_image_macro_vertex.glsl"
