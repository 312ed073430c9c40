#version 450
#extension GL_GOOGLE_include_directive : require
// grass.image: the baked top view cut by the cell's density (shaders/grass_image_fragment.glsl).
#include "grass_image_params.h"
#include "grass_image_fragment.glsl"
