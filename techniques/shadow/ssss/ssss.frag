#version 450
#extension GL_GOOGLE_include_directive : require
// shadow.ssss, final step: the blurred screen-space shadow at this very pixel.
#include "forward_lighting.glsl"

float shadow_visibility(ShadowQuery q) {
    return clamp(texelFetch(screen_shadow, ivec2(gl_FragCoord.xy), 0).r, 0.0, 1.0);
}
