#version 450
#extension GL_GOOGLE_include_directive : require
// grass.image: one horizontal quad per cell (shaders/grass_image_vertex.glsl).
#include "grass_image_params.h"
#include "grass_image_vertex.glsl"
