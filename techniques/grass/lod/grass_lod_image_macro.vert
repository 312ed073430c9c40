#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod under culling = "quadtree": the far band's macro-cell quads (shaders/grass_image_macro_vertex.glsl, drawing each cell's band).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_IMAGE
#include "grass_lod_params.h"
#include "grass_image_macro_vertex.glsl"
