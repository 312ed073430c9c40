// grass.volume's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_GRASS_VOLUME_PARAMS_H
#define CANOPY_GRASS_VOLUME_PARAMS_H

#include "param_block.h"
#include "../shaders/slice_filtering_params.h"

#define GRASS_VOLUME_PARAMS(SHADER, PLAN, DERIVED)                                                         \
    SHADER(integer, slices, (8, 1, 64), "vertical slices per direction, x and z (Lemme's Table 7.1: 16)")  \
    PLAN(integer, resolution, (256, 16, 4096), "texels of a slice across the patch (Lemme's Table 7.1: 1024)") \
    PLAN(integer, height_resolution, (64, 4, 4096), "texels of a slice up the patch's height (Lemme's Table 7.1: 128)") \
    PLAN(integer, macro_cells, (0, 0, 64), "0: one cuboid per cell over the patch's bounds; k >= 1: one cuboid per k x k macro-cell, each cell shown by repeating a bake of the patch and its 8 neighbours cut to the cell (Lemme §6.2; Table 7.2: 1-16)") \
    GRASS_SLICE_FILTERING_PARAMS(PLAN, "coverage")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(GrassVolumeParams, GRASS_VOLUME_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS GrassVolumeParams
#endif

#endif
