#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod: the far band's top view (shaders/grass_image_fragment.glsl, drawing the band lod_band gives it).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_IMAGE
#include "grass_lod_params.h"
#include "grass_image_fragment.glsl"
