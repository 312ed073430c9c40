// shadow.vsm's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_VSM_PARAMS_H
#define CANOPY_VSM_PARAMS_H

#include "param_block.h"
#include "../common/prefilter_param_list.h"

#define VSM_PARAMS(SHADER, PLAN, DERIVED) \
    PREFILTER_PARAMS(PLAN)                                                                                \
    SHADER(real, min_variance, (1e-5, 0.0, 0.01), "variance floor (normalised depth squared) against numerical acne") \
    SHADER(real, bleeding_reduction, (0.0, 0.0, 0.95),                                                     \
           "light-bleeding reduction: visibility below this is cut to 0, the rest rescaled")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(VsmParams, VSM_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS VsmParams
#endif

#endif
