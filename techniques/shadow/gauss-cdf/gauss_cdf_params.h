// shadow.gauss-cdf's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_GAUSS_CDF_PARAMS_H
#define CANOPY_GAUSS_CDF_PARAMS_H

#include "param_block.h"
#include "../common/prefilter_param_list.h"

#define GAUSS_CDF_PARAMS(SHADER, PLAN, DERIVED) \
    PREFILTER_PARAMS(PLAN)                                                                                \
    SHADER(real, min_variance, (1e-5, 0.0, 0.01), "variance floor (normalised depth squared); sigma = 0 is a hard step") \
    SHADER(boolean, exact_erf, (false), "accurate erf (Abramowitz-Stegun) instead of Winitzki's approximation")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(GaussCdfParams, GAUSS_CDF_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS GaussCdfParams
#endif

#endif
