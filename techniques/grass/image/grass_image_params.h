// grass.image's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_GRASS_IMAGE_PARAMS_H
#define CANOPY_GRASS_IMAGE_PARAMS_H

#include "param_block.h"
#include "../shaders/slice_filtering_params.h"

#define GRASS_IMAGE_PARAMS(SHADER, PLAN, DERIVED)                                                          \
    PLAN(integer, resolution, (256, 16, 4096), "texels across the baked top view of the patch (width and height)") \
    SHADER(real, slice_height, (0.1, 0.01, 1.0),                                                            \
         "the slice's height above the ground, a fraction of the patch's tallest blade (Lemme: 'a low offset'; above 0, or the ground hides it)") \
    PLAN(integer, macro_cells, (0, 0, 64), "0: one quad per cell over the patch's bounds; k >= 1: one quad per k x k macro-cell, each cell shown by repeating a bake of the patch and its 8 neighbours cut to the cell (Lemme §6.2; Table 7.2: 1-16)") \
    PLAN(real, macro_unplanarity, (0.05, 0.0, 1e4), "macro_cells on a terrain: a macro-cell whose ground departs from the bilinear patch of its corners by more than this (world units) is split in four, and again, down to single cells (Lemme L906-908 gives no value; 0: split wherever the ground is not bilinear)") \
    GRASS_SLICE_FILTERING_PARAMS(PLAN, "coverage")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(GrassImageParams, GRASS_IMAGE_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS GrassImageParams
#endif

#endif
