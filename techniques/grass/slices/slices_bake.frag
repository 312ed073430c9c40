#version 450
#extension GL_GOOGLE_include_directive : require
// grass.slices, load phase: a slice side's bake under local shading (slices_bake_fragment.glsl).
#include "slices_bake_fragment.glsl"
