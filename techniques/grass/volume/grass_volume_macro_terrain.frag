#version 450
#extension GL_GOOGLE_include_directive : require
// grass.volume with macro-cells on a terrain: each hit's lookup shifted by the ground under it
// (shaders/grass_volume_macro_fragment.glsl with GRASS_MACRO_TERRAIN).
#define GRASS_MACRO_TERRAIN
#include "grass_volume_params.h"
#include "grass_volume_macro_fragment.glsl"
