// shadow.evsm's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_EVSM_PARAMS_H
#define CANOPY_EVSM_PARAMS_H

#include "param_block.h"
#include "../common/prefilter_param_list.h"

#define EVSM_PARAMS(SHADER, PLAN, DERIVED) \
    PREFILTER_PARAMS(PLAN)                                                                                \
    SHADER(choice, components, ("4", {"2", "4"}), "positive warp only (2) or positive and negative (4)")  \
    PLAN(real, positive_exponent, (40.0, 0.0, 100.0), "c+ of exp(c+ z'), clamped to what the precision can store") \
    PLAN(real, negative_exponent, (5.0, 0.0, 100.0), "c- of -exp(-c- z'), clamped to what the precision can store") \
    SHADER(real, min_variance, (1e-5, 0.0, 0.01),                                                          \
           "variance floor in depth units (z^2, as shadow.vsm), mapped through each warp's slope")         \
    SHADER(real, bleeding_reduction, (0.0, 0.0, 0.95), "as in shadow.vsm")                                 \
    DERIVED(real, c_pos, "positive_exponent clamped to what the precision can store")                      \
    DERIVED(real, c_neg, "negative_exponent clamped to what the precision can store")

// components' choices, in declaration order.
#define EVSM_COMPONENTS_2 0
#define EVSM_COMPONENTS_4 1

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(EvsmParams, EVSM_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS EvsmParams
#endif

#endif
