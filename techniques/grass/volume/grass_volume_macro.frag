#version 450
#extension GL_GOOGLE_include_directive : require
// grass.volume with macro-cells: the ray walk through a macro-cell's cells (shaders/grass_volume_macro_fragment.glsl).
#include "grass_volume_params.h"
#include "grass_volume_macro_fragment.glsl"
