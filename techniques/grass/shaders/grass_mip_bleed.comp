#version 450
#extension GL_GOOGLE_include_directive : require
// grass_mip_bleed.glsl with a companion array (a normal, or a BTF slice's lit rows).
#define GRASS_MIP_COMPANION
#include "grass_mip_bleed.glsl"
