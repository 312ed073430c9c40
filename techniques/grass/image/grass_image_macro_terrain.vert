#version 450
#extension GL_GOOGLE_include_directive : require
// grass.image with macro-cells that follow a terrain: each quad's corners on the field's grid
// heights (shaders/grass_image_macro_vertex.glsl with GRASS_MACRO_TERRAIN).
#define GRASS_MACRO_TERRAIN
#include "grass_image_params.h"
#include "grass_image_macro_vertex.glsl"
