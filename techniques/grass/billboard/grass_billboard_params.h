// grass.billboard's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_GRASS_BILLBOARD_PARAMS_H
#define CANOPY_GRASS_BILLBOARD_PARAMS_H

#include "param_block.h"
#include "../shaders/slice_filtering_params.h"

#define GRASS_BILLBOARD_PARAMS(SHADER, PLAN, DERIVED)                                                     \
    PLAN(integer, resolution, (256, 16, 4096), "texels across each baked image of the patch (width and height)") \
    SHADER(choice, orientation, ("crossed", {"crossed", "camera_facing"}),                                \
           "two fixed quads crossing at the cell's centre, or one quad turned about y to face the camera") \
    GRASS_SLICE_FILTERING_PARAMS(PLAN, "coverage")

CANOPY_BEGIN_NAMESPACE
CANOPY_CONST int GRASS_BILLBOARD_CROSSED = 0;
CANOPY_CONST int GRASS_BILLBOARD_CAMERA_FACING = 1;
CANOPY_PARAM_BLOCK(GrassBillboardParams, GRASS_BILLBOARD_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS GrassBillboardParams
#endif

#endif
