// shadow.pcf's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_PCF_PARAMS_H
#define CANOPY_PCF_PARAMS_H

#include "param_block.h"
#include "../common/shadow_map_param_list.h"

#define PCF_PARAMS(SHADER, PLAN, DERIVED)                                                                  \
    SHADOW_MAP_PARAMS(SHADER, PLAN)                                                                        \
    SHADER(integer, kernel, (3, 1, 11), "kernel width k: k*k depth tests per pixel")                       \
    SHADER(choice, pattern, ("grid", {"grid", "poisson"}),                                                 \
           "sample layout: k x k texel grid, or k*k Poisson-disk samples of radius k/2")                  \
    SHADER(boolean, hardware_2x2, (false), "each sample is a bilinear 2x2 depth compare (LINEAR compare sampler)") \
    SHADER(boolean, receiver_plane, (true),                                                                \
           "compare each tap with the receiver plane's depth there (else bias for the whole kernel)")     \
    DERIVED(integer, count, "taps per pixel: k*k")                                                         \
    DERIVED(real, reach, "the farthest tap's distance from the centre in texels")

// pattern's choices, in declaration order.
#define PCF_PATTERN_GRID 0
#define PCF_PATTERN_POISSON 1

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(PcfParams, PCF_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS PcfParams
#endif

#endif
