#version 450
#extension GL_GOOGLE_include_directive : require
// grass.geometry: the blades' outline and shading (shaders/grass_blades_fragment.glsl).
#include "grass_geometry_params.h"
#include "grass_blades_fragment.glsl"
