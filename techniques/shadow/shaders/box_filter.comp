#version 450
#extension GL_GOOGLE_include_directive : require
// Box filter: the mean of 2r+1 texels, every channel. Two passes give a (2r+1)^2 box.
#include "separable_filter.glsl"

vec4 filter_texel(ivec2 xy) {
    vec4 sum = vec4(0.0);
    for (int i = -filter_pass.radius; i <= filter_pass.radius; ++i) sum += fetch(xy, i);
    return sum / float(2 * filter_pass.radius + 1);
}
