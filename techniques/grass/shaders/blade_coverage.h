// How a blade's outline cuts (the `coverage` parameter of grass.geometry and grass.lod): GLSL and
// C++ (shared_math.h).
#ifndef CANOPY_GRASS_BLADE_COVERAGE_H
#define CANOPY_GRASS_BLADE_COVERAGE_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE
CANOPY_CONST int GRASS_COVERAGE_ALPHA_TEST = 0;
CANOPY_CONST int GRASS_COVERAGE_ALPHA_TO_COVERAGE = 1;
CANOPY_END_NAMESPACE

#endif
