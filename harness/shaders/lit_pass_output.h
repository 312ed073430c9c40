// What the lit pass writes per pixel (GLSL and C++): RGB = radiance; A = the visibility of the
// shadow light it multiplied into the light's irradiance, or VISIBILITY_NOT_LIT where it did not
// light the surface (facing away from the light, outside a spot's cone) or drew nothing (the
// clear value). The runner reads A back as the technique's visibility at its pixel centres
// (harness/core/pixel_visibility.hpp); the images users see get A = 1.
#ifndef CANOPY_LIT_PASS_OUTPUT_H
#define CANOPY_LIT_PASS_OUTPUT_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

CANOPY_CONST float VISIBILITY_NOT_LIT = -1.0f;

CANOPY_FN vec4 lit_pass_output(vec3 radiance, bool lit, float visibility) {
    return vec4(radiance, lit ? visibility : VISIBILITY_NOT_LIT);
}

CANOPY_END_NAMESPACE

#endif
