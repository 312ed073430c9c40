// shadow.msm's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_MSM_PARAMS_H
#define CANOPY_MSM_PARAMS_H

#include "param_block.h"
#include "../common/prefilter_param_list.h"

// Peters & Klein store the quantised moments in 16-bit unorm; rgba16f is offered too.
#define MSM_PARAMS(SHADER, PLAN, DERIVED) \
    PREFILTER_RESOLUTION_PARAM(PLAN)                                                                      \
    PLAN(choice, precision, ("fp32", {"fp32", "fp16", "unorm16"}),                                         \
         "moment storage: 32-bit float, 16-bit float, or 16-bit unorm (the paper's)")                     \
    PREFILTER_FILTER_PARAM(PLAN)                                                                           \
    SHADER(real, moment_bias, (3e-5, 0.0, 0.01),                                                           \
           "blend towards well-conditioned target moments (3e-5 for fp32, 6e-5 suits 16 bits)")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(MsmParams, MSM_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS MsmParams
#endif

#endif
