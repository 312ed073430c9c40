#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod under culling = "quadtree" with middle_per_sample: the macro-cells' ray walk once per covered sample (shaders/grass_volume_macro_fragment.glsl).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_VOLUME
#define GRASS_LOD_VOLUME_LEVELS
#define GRASS_VOLUME_PER_SAMPLE
#include "grass_lod_params.h"
#include "grass_volume_macro_fragment.glsl"
