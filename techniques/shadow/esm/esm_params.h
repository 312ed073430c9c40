// shadow.esm's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_ESM_PARAMS_H
#define CANOPY_ESM_PARAMS_H

#include "param_block.h"
#include "../common/prefilter_param_list.h"

#define ESM_PARAMS(SHADER, PLAN, DERIVED) \
    PREFILTER_PARAMS(PLAN)                                                                                \
    SHADER(real, exponent, (80.0, 1.0, 200.0),                                                             \
           "c in exp(c z); linear storage holds it up to c = 11 (fp16) or 84 (fp32), "                    \
           "larger c needs log_space")                                                                     \
    SHADER(boolean, log_space, (false), "store c z and filter in log space (log-sum-exp), so no exponent overflows")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(EsmParams, ESM_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS EsmParams
#endif

#endif
