#version 450
#extension GL_GOOGLE_include_directive : require
// grass.volume: the ray cast through a cell's slices (shaders/grass_volume_fragment.glsl).
#include "grass_volume_params.h"
#include "grass_volume_fragment.glsl"
