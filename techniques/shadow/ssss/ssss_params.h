// shadow.ssss's parameters, written once for C++ and GLSL (harness/shaders/param_block.h). The
// camera pass, the coarse map's dilation and the screen-space blur all read them from the frame
// uniforms (frame.technique).
#ifndef CANOPY_SSSS_PARAMS_H
#define CANOPY_SSSS_PARAMS_H

#include "param_block.h"
#include "../common/shadow_map_param_list.h"

#define SSSS_PARAMS(SHADER, PLAN, DERIVED)                                                                \
    SHADOW_MAP_PARAMS(SHADER, PLAN)                                                                       \
    SHADER(integer, kernel, (11, 1, 63), "Gaussian taps K per axis (the paper's K5, K11, K23)")           \
    SHADER(integer, coarse_block, (4, 1, 16),                                                             \
           "shadow-map texels per coarse-map texel in each axis (block minimum)")                         \
    SHADER(real, occluder_distance, (1.0, 0.0, 1.0),                                                      \
           "the paper's dilation factor (6.2.1): the largest distance from a caster to the "              \
           "receiver of its penumbra, as a fraction of the light's depth range")                          \
    SHADER(real, depth_error, (0.05, 0.0, 1.0),                                                           \
           "a tap whose distance to the observer differs by more than this fraction from "                \
           "where its ray meets the centre pixel's tangent plane is another surface")                     \
    SHADER(boolean, lazy, (true),                                                                         \
           "lazy shadowing (6.3.2): shadow-test hidden taps on the tangent plane instead of dropping them")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(SsssParams, SSSS_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS SsssParams
#endif

#endif
