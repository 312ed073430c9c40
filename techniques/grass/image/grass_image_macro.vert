#version 450
#extension GL_GOOGLE_include_directive : require
// grass.image with macro-cells: one quad per macro-cell (shaders/grass_image_macro_vertex.glsl).
#include "grass_image_params.h"
#include "grass_image_macro_vertex.glsl"
