#version 450
#extension GL_GOOGLE_include_directive : require
// grass.slices: the baked BTF rows cut by the cell's density, lit by the interpolated light
// (shaders/grass_slices_fragment.glsl).
#include "grass_slices_params.h"
#include "grass_slices_fragment.glsl"
