#version 450
#extension GL_GOOGLE_include_directive : require
// grass.lod's near-band cull (culling = "gpu"): the copies whose box may be seen and comes within
// geometry_none, beyond which a cell has no blades left (shaders/grass_cull.glsl). A cell's band is
// set by its centre's distance, never below its box's nearest point's, so no drawn blade is culled.
#include "grass_lod_params.h"
#define FRAME_BINDING 0
#include "frame_uniforms.glsl"
#define GRASS_CULL_MAX_DISTANCE frame.technique.geometry_none
#include "grass_cull.glsl"
