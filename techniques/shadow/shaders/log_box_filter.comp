#version 450
#extension GL_GOOGLE_include_directive : require
// Log-space box filter for ESM (channel r holds c*z = log(exp(c z))): the log of the mean of
// exponentials, computed relative to the centre so nothing overflows (Annen et al. 2008).
#include "separable_filter.glsl"

vec4 filter_texel(ivec2 xy) {
    float centre = fetch(xy, 0).r;
    float sum = 0.0;
    for (int i = -filter_pass.radius; i <= filter_pass.radius; ++i) sum += exp(fetch(xy, i).r - centre);
    return vec4(centre + log(sum / float(2 * filter_pass.radius + 1)), 0.0, 0.0, 1.0);
}
