#version 450
#extension GL_GOOGLE_include_directive : require
// grass.slices with bake_shadows: a slice side's bake with the blades' shadows in its rows'
// alpha (slices_bake_fragment.glsl).
#define SLICES_BAKE_SHADOWS
#include "slices_bake_fragment.glsl"
