// What a baked texel of an image-based grass representation (volume, BTF slices, image slice,
// billboards) holds, and how its mips are made and read (GLSL and C++: common/mip_chain.cpp builds
// the same levels on the CPU for the tests, shaders/grass_mip_*.comp on the GPU at load).
//
// A bake writes two images per slice (Lemme L406: "a blade's density threshold map for every
// slice" beside the colour):
// - the colour: rgb the blade's colour, alpha the share of the texel blades cover (1 or 0 in a
//   bake at the slice's resolution); its mips filtered by mip_filters.h's filter of choice;
// - the blade map: x, y the smallest and largest density threshold of the blades the texel shows
//   (one blade: x = y), z, w the root of those blades in patch x and z (their coverage-weighted
//   mean), so a representation thins and hands over the blades a texel shows by their own
//   density and distance, not the cell's. Texels that show no blade hold BLADE_MAP_EMPTY.
//
// The thresholds cannot be averaged (half of one blade and half of another is no blade's
// threshold), so the blade map's mips follow a rule of their own (blade_map_reduce): the range of
// the footprint's thresholds and the mean of its roots. A filtered texel drawn at density ld in
// a band (lo, hi] keeps the share of its range inside (lo ld, hi ld], reading the footprint's
// thresholds as spread evenly over the range (blade_texel_share): exact at level 0, where the
// range is one threshold, and, where a footprint's n blades have thresholds uniform in ]0, 1]
// (what the patch's generator draws without clustering, Lemme §4.1.3), off by at most about
// 1 / (n + 1) of the share on average (the range's ends sit that far inside ]0, 1]).
#ifndef CANOPY_GRASS_BLADE_TEXELS_H
#define CANOPY_GRASS_BLADE_TEXELS_H

#include "shared_math.h"
#include "lod_selection.h"

CANOPY_BEGIN_NAMESPACE

// A blade map texel showing no blade: thresholds no density reaches, the root at the origin.
CANOPY_CONST vec4 BLADE_MAP_EMPTY = vec4(2.0f, 2.0f, 0.0f, 0.0f);

// The alpha test's reference a_r where no MSAA turns alpha into coverage, and the reference
// Lemme's coverage-preserving filter keeps the coverage at (eq 4.11). Lemme asks for "a high
// alpha reference value" and gives none; canopy takes 0.5, where a bilinear level 0 puts a blade's
// edge.
CANOPY_CONST float GRASS_ALPHA_REFERENCE = 0.5f;

// Whether blade map texel `b` shows a blade.
CANOPY_FN bool blade_map_covered(vec4 b) { return b.x <= 1.0f; }

// One texel of the next level from the 2 x 2 it covers (and their colours' alphas, the share each
// covers): the smallest and largest threshold of the covered ones, their roots weighted by
// coverage; BLADE_MAP_EMPTY where none is covered.
CANOPY_FN vec4 blade_map_reduce(vec4 b0, vec4 b1, vec4 b2, vec4 b3, vec4 alphas) {
    float lo = 2.0f;
    float hi = -1.0f;
    vec2 root = vec2(0.0f);
    float weight = 0.0f;
    if (blade_map_covered(b0)) { lo = min(lo, b0.x); hi = max(hi, b0.y); root += vec2(b0.z, b0.w) * alphas.x; weight += alphas.x; }
    if (blade_map_covered(b1)) { lo = min(lo, b1.x); hi = max(hi, b1.y); root += vec2(b1.z, b1.w) * alphas.y; weight += alphas.y; }
    if (blade_map_covered(b2)) { lo = min(lo, b2.x); hi = max(hi, b2.y); root += vec2(b2.z, b2.w) * alphas.z; weight += alphas.z; }
    if (blade_map_covered(b3)) { lo = min(lo, b3.x); hi = max(hi, b3.y); root += vec2(b3.z, b3.w) * alphas.w; weight += alphas.w; }
    if (hi < 0.0f) return BLADE_MAP_EMPTY;
    if (weight > 0.0f) root = root / weight;
    return vec4(lo, hi, root.x, root.y);
}

// Lemme's colour bleeding (eq 4.16) carried to the blade map: a texel that shows no blade takes
// the next level's texel (read with nearest filtering), so a filtered lookup at a blade's edge mixes
// blades' thresholds and roots only; the colour's alpha still says how much a blade covers.
CANOPY_FN vec4 blade_map_bleed(vec4 b, vec4 next_level) { return blade_map_covered(b) ? b : next_level; }

// The screen-door values (lod_band_interval, lod_selection.h) at which a texel's covered part is
// drawn by a representation drawing the band (lo, hi] of the blades (lod_band; (0, 1] alone) at
// local density ld, each cut crossed over `window` of `width` (binary alone): the texel's
// blades read as thresholds spread evenly over `range`, each drawn at its share of the band. The
// interval's length is that share: the part of the range the density keeps inside the band (a
// binary window); a range of one threshold (a level-0 texel) gets exactly the interval of its
// blade, so a blade and the texel showing it share its pixels out without gap or overlap.
CANOPY_FN vec2 blade_texel_interval(vec2 range, float ld, vec2 band, int window, float width) {
    if (!(range.y > range.x)) return lod_band_interval(range.x, ld, band, window, width);
    if (!(ld > 0.0f)) return vec2(0.0f, 0.0f);
    float a = range.x / ld;
    float b = min(range.y, ld) / ld;
    if (!(b > a)) return vec2(0.0f, 0.0f);
    float kept = clamp((min(range.y, ld) - range.x) / (range.y - range.x), 0.0f, 1.0f);
    // Each band's end: the kept part's mean share beyond its cut (lod_beyond_mean).
    float start = kept * (1.0f - lod_beyond_mean(a, b, band.x, window, width));
    float end = kept * (1.0f - lod_beyond_mean(a, b, band.y, window, width));
    return vec2(start, max(start, end));  // rounding may take a band that keeps nothing a hair below 0
}

// The share of a texel's covered part that a representation drawing the band (lo, hi] keeps at
// local density ld with binary cuts: the part of the threshold range `range` inside
// (lo ld, hi ld], the range read as evenly filled; a range of one threshold (a level-0 texel) is
// kept whole or not at all, as grass_blade_in_band keeps a blade. blade_texel_interval's length.
CANOPY_FN float blade_texel_share(vec2 range, float ld, vec2 band) {
    float lo = band.x * ld;
    float hi = band.y * ld;
    if (!(range.y > range.x)) return (range.x > lo && range.x <= hi) ? 1.0f : 0.0f;
    float width = range.y - range.x;
    return clamp((hi - range.x) / width, 0.0f, 1.0f) - clamp((lo - range.x) / width, 0.0f, 1.0f);
}

CANOPY_END_NAMESPACE

#endif
