// grass.slices' parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_GRASS_SLICES_PARAMS_H
#define CANOPY_GRASS_SLICES_PARAMS_H

#include "param_block.h"
#include "../shaders/slice_filtering_params.h"

#define GRASS_SLICES_PARAMS(SHADER, PLAN, DERIVED)                                                          \
    SHADER(integer, slices, (8, 1, 64), "vertical slices per direction, x and z (Boulanger gives no count; grass.volume's default)") \
    PLAN(integer, resolution, (256, 16, 4096), "texels of a slice across the patch, and of the horizontal slice each way") \
    PLAN(integer, height_resolution, (64, 4, 4096), "texels of a vertical slice up the patch's height") \
    SHADER(real, slice_height, (0.1, 0.01, 1.0),                                                             \
         "the horizontal slice's height above the ground, a fraction of the tallest blade (Boulanger: 'close to the bottom of the patch')") \
    PLAN(boolean, neighbours, (true), "bake the patch with its 8 neighbours, cut to the cell (Boulanger §4.2.3: else blades are cut between patches), or the patch alone over its bounds") \
    PLAN(integer, shadow_resolution, (0, 0, 8192), "0: no shadows in the bake (the family's local shading); else bake the blades' shadows into the rows (Boulanger L1034), from one depth view per baked light direction this many texels a side") \
    GRASS_SLICE_FILTERING_PARAMS(PLAN, "max_alpha")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(GrassSlicesParams, GRASS_SLICES_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS GrassSlicesParams
#endif

#endif
