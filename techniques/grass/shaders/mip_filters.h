// The mip filters the grass theses argue about, for slices whose texels are a colour and an
// alpha (GLSL and C++: common/mip_chain.hpp builds chains with them and the tests check them):
// - the box filter (Lemme eq 4.7-4.8, Boulanger eq 4.15): the mean of the four texels;
// - Boulanger's max-alpha filter (eq 4.16-4.18): the alpha-weighted colour, the largest alpha;
// - Lemme's coverage-preserving filter (eq 4.9-4.15): the same colour and largest alpha, then
//   the level's alphas scaled so that as many texels pass the alpha test at a_r as in level 0
//   (the scale is a reduction over the whole level: mip_chain.cpp finds it);
// - Lemme's colour bleeding (eq 4.16): a texel's transparent part takes the next level's colour.
#ifndef CANOPY_GRASS_MIP_FILTERS_H
#define CANOPY_GRASS_MIP_FILTERS_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// Eq 4.7-4.8 (Boulanger eq 4.15): rgb and alpha each the mean of the four.
CANOPY_FN vec4 mip_box(vec4 t0, vec4 t1, vec4 t2, vec4 t3) { return (t0 + t1 + t2 + t3) * 0.25f; }

// Eq 4.9-4.10 (Boulanger eq 4.17-4.18): the colour weighted by alpha; s_a = 1 where all four are
// transparent, so their colour is 0, not 0 / 0.
CANOPY_FN vec3 mip_alpha_weighted_colour(vec4 t0, vec4 t1, vec4 t2, vec4 t3) {
    float sum = t0.w + t1.w + t2.w + t3.w;
    float s_a = sum == 0.0f ? 1.0f : sum;
    return (vec3(t0) * t0.w + vec3(t1) * t1.w + vec3(t2) * t2.w + vec3(t3) * t3.w) / s_a;
}

// Boulanger eq 4.16-4.18 (Lemme eq 4.12 before its rescaling): alpha-weighted colour, max alpha.
CANOPY_FN vec4 mip_max_alpha(vec4 t0, vec4 t1, vec4 t2, vec4 t3) {
    return vec4(mip_alpha_weighted_colour(t0, t1, t2, t3), max(max(t0.w, t1.w), max(t2.w, t3.w)));
}

// A supersampled bake brought down one step (canopy's anti-aliased level 0, Lemme L514): the
// share of the four covered (their mean alpha) and their alpha-weighted colour.
CANOPY_FN vec4 mip_resolve(vec4 t0, vec4 t1, vec4 t2, vec4 t3) {
    return vec4(mip_alpha_weighted_colour(t0, t1, t2, t3), (t0.w + t1.w + t2.w + t3.w) * 0.25f);
}

// Eq 4.14-4.15: a texel of a max-alpha level with its alpha scaled by scale_coverage = a_r / a'_r,
// kept in [0, 1].
CANOPY_FN vec4 mip_scale_alpha(vec4 t, float scale_coverage) {
    return vec4(vec3(t), clamp(t.w * scale_coverage, 0.0f, 1.0f));
}

// Eq 4.16: C'_i = A_i C_i + (1 - A_i) C_{i+1}, the next level's texel read with nearest filtering.
CANOPY_FN vec4 mip_bleed(vec4 t, vec4 next_level) {
    return vec4(vec3(t) * t.w + vec3(next_level) * (1.0f - t.w), t.w);
}

// A companion texel (a normal, or a BTF slice's lit row and its light's visibility) of the next
// level: the four weighted by their colours' alphas `alphas`, their mean where none is covered.
CANOPY_FN vec4 mip_companion(vec4 t0, vec4 t1, vec4 t2, vec4 t3, vec4 alphas) {
    float sum = alphas.x + alphas.y + alphas.z + alphas.w;
    if (sum == 0.0f) return (t0 + t1 + t2 + t3) * 0.25f;
    return (t0 * alphas.x + t1 * alphas.y + t2 * alphas.z + t3 * alphas.w) / sum;
}

// Eq 4.16 for a companion texel whose colour has alpha `alpha`: its transparent part from the next
// level's texel (all four channels).
CANOPY_FN vec4 mip_bleed_companion(vec4 t, float alpha, vec4 next_level) { return t * alpha + next_level * (1.0f - alpha); }

CANOPY_END_NAMESPACE

#endif
