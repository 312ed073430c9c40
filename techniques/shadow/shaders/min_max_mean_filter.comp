#version 450
#extension GL_GOOGLE_include_directive : require
// Power-CDF prefilter (Gumbau 2011, section 7.2.2): channel r = minimum, g = maximum,
// b = mean of 2r+1 texels. Min and max are separable exactly; the mean as a box.
#include "separable_filter.glsl"

vec4 filter_texel(ivec2 xy) {
    vec4 centre = fetch(xy, 0);
    float lo = centre.r, hi = centre.g, sum = 0.0;
    for (int i = -filter_pass.radius; i <= filter_pass.radius; ++i) {
        vec4 t = fetch(xy, i);
        lo = min(lo, t.r);
        hi = max(hi, t.g);
        sum += t.b;
    }
    return vec4(lo, hi, sum / float(2 * filter_pass.radius + 1), 1.0);
}
