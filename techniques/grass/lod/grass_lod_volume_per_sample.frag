#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod with middle_per_sample: the middle band's ray cast once per covered sample (shaders/grass_volume_fragment.glsl).
#define GRASS_LOD_REPRESENTATION GRASS_LOD_VOLUME
#define GRASS_LOD_VOLUME_LEVELS
#define GRASS_VOLUME_PER_SAMPLE
#include "grass_lod_params.h"
#include "grass_volume_fragment.glsl"
