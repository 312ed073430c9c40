// The parameters every shadow-map technique declares first, as entries of its params header's
// list (harness/shaders/param_block.h): map size and depth format shape the plan, the bias
// reaches the shaders as frame.technique.bias_constant and .bias_slope.
#ifndef CANOPY_SHADOW_MAP_PARAM_LIST_H
#define CANOPY_SHADOW_MAP_PARAM_LIST_H

#define SHADOW_MAP_PARAMS(SHADER, PLAN)                                                                    \
    PLAN(integer, resolution, (1024, 16, 8192), "shadow-map width and height in texels")                   \
    PLAN(choice, depth_format, ("d32f", {"d32f", "d16"}), "shadow-map depth format: 32-bit float or 16-bit unorm") \
    SHADER(real, bias_constant, (0.0005, 0.0, 0.05), "constant depth bias as a fraction of the light's depth range") \
    SHADER(real, bias_slope, (1.0, 0.0, 16.0),                                                             \
           "slope-scaled bias: multiples of the receiver plane's depth change across one texel")

#endif
