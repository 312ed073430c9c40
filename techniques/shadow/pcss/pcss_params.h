// shadow.pcss's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_PCSS_PARAMS_H
#define CANOPY_PCSS_PARAMS_H

#include "param_block.h"
#include "../common/shadow_map_param_list.h"

#define PCSS_PARAMS(SHADER, PLAN, DERIVED)                                                                \
    SHADOW_MAP_PARAMS(SHADER, PLAN)                                                                       \
    SHADER(integer, blocker_search, (5, 1, 16), "blocker-search grid width Bs: Bs x Bs samples")          \
    SHADER(integer, kernel, (5, 1, 31), "PCF grid width K: K x K samples spread over the penumbra")      \
    SHADER(real, max_radius, (64.0, 1.0, 512.0), "cap on the search and filter radius in texels (huge lights)")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(PcssParams, PCSS_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS PcssParams
#endif

#endif
