#version 450
#extension GL_GOOGLE_include_directive : require
// grass.image with macro-cells: the tiled top view per cell (shaders/grass_image_macro_fragment.glsl).
#include "grass_image_params.h"
#include "grass_image_macro_fragment.glsl"
