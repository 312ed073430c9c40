// shadow.hard's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_HARD_PARAMS_H
#define CANOPY_HARD_PARAMS_H

#include "param_block.h"
#include "../common/shadow_map_param_list.h"

#define HARD_PARAMS(SHADER, PLAN, DERIVED) SHADOW_MAP_PARAMS(SHADER, PLAN)

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(HardParams, HARD_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS HardParams
#endif

#endif
