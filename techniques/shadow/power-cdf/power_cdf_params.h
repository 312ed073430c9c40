// shadow.power-cdf's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_POWER_CDF_PARAMS_H
#define CANOPY_POWER_CDF_PARAMS_H

#include "param_block.h"
#include "../common/prefilter_param_list.h"

#define POWER_CDF_PARAMS(SHADER, PLAN, DERIVED) \
    PREFILTER_PARAMS(PLAN)                                                                                \
    DERIVED(real, depth_roundoff, "two units of roundoff of the stored depths, relative (from precision)")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(PowerCdfParams, POWER_CDF_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS PowerCdfParams
#endif

#endif
