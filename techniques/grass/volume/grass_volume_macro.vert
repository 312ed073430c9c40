#version 450
#extension GL_GOOGLE_include_directive : require
// grass.volume with macro-cells: one cuboid per macro-cell (shaders/grass_volume_macro_vertex.glsl).
#include "grass_volume_params.h"
#include "grass_volume_macro_vertex.glsl"
