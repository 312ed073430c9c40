// grass.geometry's parameters, written once for C++ and GLSL (harness/shaders/param_block.h).
#ifndef CANOPY_GRASS_GEOMETRY_PARAMS_H
#define CANOPY_GRASS_GEOMETRY_PARAMS_H

#include "param_block.h"
#include "../shaders/blade_coverage.h"

#define GRASS_GEOMETRY_PARAMS(SHADER, PLAN, DERIVED)                                                        \
    PLAN(integer, samples, (4, 1, 4),                                                                       \
         "MSAA samples of the blade pass: 1 or 4 (lavapipe's; Boulanger used >= 6 on a GPU, L1314)")         \
    SHADER(choice, coverage, ("alpha_to_coverage", {"alpha_test", "alpha_to_coverage"}),                   \
           "how the blade outline cuts: a hard alpha test, or a smooth alpha turned into sample coverage")  \
    PLAN(choice, culling, ("none", {"none", "gpu"}),                                                        \
         "none: every cell's copy is drawn; gpu: a compute pass keeps the copies whose box may be seen (and within max_distance) and writes the draw's instance count") \
    PLAN(real, max_distance, (0.0, 0.0, 1e6),                                                                  \
         "culling = gpu: copies whose box lies farther than this from the eye are not drawn (world units; 0: no limit)")

CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(GrassGeometryParams, GRASS_GEOMETRY_PARAMS)
CANOPY_END_NAMESPACE

#ifndef __cplusplus
#define TECHNIQUE_PARAMS GrassGeometryParams
#endif

#endif
