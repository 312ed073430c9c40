// Which representation draws a blade where two meet (Boulanger 2008 §4.2.5, eq 4.3-4.6 and
// Algorithm 1; Lemme 2012 §5.4, eq 5.22-5.26): the blades of a cell are split by their density
// thresholds, the low thresholds going to the farther representation as the camera recedes, so
// that a transition moves blades one by one instead of swapping the whole cell. GLSL and C++
// (shared_math.h): grass.lod's shaders run lod_cuts, lod_band and lod_volume_level_band (the cuts
// at each blade's root's distance: grass_lod_band.glsl) and lod_band_interval (the window each cut
// is crossed over: Boulanger's Algorithm 1 / eq 4.6, Lemme's eq 5.26, or binary). The weights
// (eq 4.3-4.5), lod_far_opacity / lod_near_opacity, lod_in_first / lod_in_second and the
// uncentred lod_*_opacity_smooth are the theses' own forms, which the tests hold the drawn ones to.
//
// Choices where the theses are silent or wrong (techniques/grass/README.md, "Transitions"):
// - ω_max (Algorithm 1) is not given: canopy takes 0.05, so at most a tenth of the local density
//   is semi-transparent, in the middle of a band; ω_0 = 0.05 as Boulanger's.
// - Boulanger's window [(w - ω) ld, (w + ω) ld] still straddles 0 at w = 0 (and ld at w = 1), so
//   blades would stay half transparent in a representation drawn alone. canopy centres the
//   window at (w (1 + 2ω) - ω) ld: at w = 0 the near representation draws every blade opaque,
//   at w = 1 the far one does, and the two opacities of a blade always sum to 1.
// - Lemme's eq 5.25 gives both representations "bdth <= w ld" with w_2 = 1 - w_1, which draws
//   some blades twice and drops others; canopy uses the complementary test: the first
//   representation keeps bdth <= w_1 ld, the second w_1 ld < bdth <= ld.
// - Eq 5.26 divides by the local density: where it is 0 no blade is drawn (thresholds are > 0).
#ifndef CANOPY_GRASS_LOD_SELECTION_H
#define CANOPY_GRASS_LOD_SELECTION_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

CANOPY_CONST float LOD_OMEGA_MAX = 0.05f;  // canopy's choice (see above)
CANOPY_CONST float LOD_OMEGA_0 = 0.05f;    // Boulanger's (Fig 4.13)
CANOPY_CONST float LOD_MIN_DENSITY = 0.01f;  // Algorithm 1: below it, nothing is drawn

// Eq 4.3: the geometry's weight, 1 up to minGeom, 0 from maxGeom on.
CANOPY_FN float lod_weight_geometry(float d, float min_geom, float max_geom) {
    return clamp((d - max_geom) / (min_geom - max_geom), 0.0f, 1.0f);
}

// Eq 4.4: the vertical slices' weight, rising over [minGeom, maxGeom], falling over [minBTF, maxBTF].
CANOPY_FN float lod_weight_vertical_slices(float d, float min_geom, float max_geom, float min_btf, float max_btf) {
    return clamp((d - min_geom) / (max_geom - min_geom), 0.0f, 1.0f) *
           clamp((d - max_btf) / (min_btf - max_btf), 0.0f, 1.0f);
}

// Eq 4.5: the horizontal slice's weight, 1 - w_g (not w_g, as the text after Algorithm 1 says).
CANOPY_FN float lod_weight_horizontal_slice(float d, float min_geom, float max_geom) {
    return 1.0f - lod_weight_geometry(d, min_geom, max_geom);
}

// Fig 4.13 / Algorithm 1: the half-width of the transition window, smallest at w = 0 and 1.
CANOPY_FN float lod_window(float w) {
    return LOD_OMEGA_MAX * (LOD_OMEGA_0 + (1.0f - LOD_OMEGA_0) * (1.0f - abs(2.0f * clamp(w, 0.0f, 1.0f) - 1.0f)));
}

// The share of a blade (threshold dth, local density ld) the far representation draws at the
// far weight w (w_vs of eq 4.4, or w_2): Algorithm 1's opacity with canopy's centred window;
// 0 where the blade is thinned away (dth > ld) or there is no grass (ld < 0.01).
CANOPY_FN float lod_far_opacity(float dth, float ld, float w) {
    if (ld < LOD_MIN_DENSITY || dth > ld) return 0.0f;
    // The ends exactly, whatever the rounding of the window's edge at dth = ld.
    if (w <= 0.0f) return 0.0f;
    if (w >= 1.0f) return 1.0f;
    float omega = lod_window(w);
    float centre = clamp(w, 0.0f, 1.0f) * (1.0f + 2.0f * omega) - omega;
    return clamp(((centre + omega) * ld - dth) / (2.0f * omega * ld), 0.0f, 1.0f);
}

// The near representation's share (eq 4.6): the complement, 0 where the blade is not drawn.
CANOPY_FN float lod_near_opacity(float dth, float ld, float w) {
    if (ld < LOD_MIN_DENSITY || dth > ld) return 0.0f;
    return 1.0f - lod_far_opacity(dth, ld, w);
}

// Lemme eq 5.25 made complementary: the first representation (weight w1) keeps the blades with
// bdth <= w1 ld, the second the rest of those the density keeps.
CANOPY_FN bool lod_in_first(float bdth, float ld, float w1) { return bdth <= clamp(w1, 0.0f, 1.0f) * ld; }
CANOPY_FN bool lod_in_second(float bdth, float ld, float w1) {
    return bdth <= ld && !lod_in_first(bdth, ld, w1);
}

// Lemme eq 5.26 (a smoothstep window of half-width eps around w1 in bdth / ld) and its complement,
// 0 where no grass is (ld = 0) instead of a division by zero.
CANOPY_FN float lod_first_opacity_smooth(float bdth, float ld, float w1, float eps) {
    if (!(ld > 0.0f) || bdth > ld) return 0.0f;
    return 1.0f - smoothstep(w1 - eps, w1 + eps, bdth / ld);
}
CANOPY_FN float lod_second_opacity_smooth(float bdth, float ld, float w1, float eps) {
    if (!(ld > 0.0f) || bdth > ld) return 0.0f;
    return smoothstep(w1 - eps, w1 + eps, bdth / ld);
}

// How a blade crosses a cut between two representations (grass.lod's `transition`): at once
// (binary, Lemme eq 5.25 made complementary), or over a window of thresholds around the cut in
// which its opacity moves from the nearer representation to the farther one: Boulanger's linear
// ramp whose half-width shrinks toward the band's ends (Algorithm 1, eq 4.6; lod_window's shape
// with ω_max = `width`), or Lemme's smoothstep of fixed half-width ε = `width` (eq 5.26).
CANOPY_CONST int GRASS_LOD_WINDOW_BINARY = 0;
CANOPY_CONST int GRASS_LOD_WINDOW_LINEAR = 1;      // Boulanger Algorithm 1, eq 4.6
CANOPY_CONST int GRASS_LOD_WINDOW_SMOOTHSTEP = 2;  // Lemme eq 5.26

// The window's half-width around cut c: Boulanger's ω(w) (Fig 4.13) or Lemme's ε.
CANOPY_FN float lod_window_half_width(float c, int window, float width) {
    if (window == GRASS_LOD_WINDOW_LINEAR)
        return width * (LOD_OMEGA_0 + (1.0f - LOD_OMEGA_0) * (1.0f - abs(2.0f * clamp(c, 0.0f, 1.0f) - 1.0f)));
    return width;
}

// The window's upper end: canopy centres it at c (1 + 2 ω) - ω (see above), so at c = 0 it lies
// wholly at or below 0 and at c = 1 wholly at or above 1.
CANOPY_FN float lod_window_top(float c, float half_width) { return clamp(c, 0.0f, 1.0f) * (1.0f + 2.0f * half_width); }

// Whether cut c is crossed at once: a binary window, no width, or a cut at 0 or 1, where the
// window lies wholly outside ]0, 1] (exactly the binary cut there, whatever its edge's rounding).
CANOPY_FN bool lod_cut_is_step(float c, int window, float width) {
    return window == GRASS_LOD_WINDOW_BINARY || !(width > 0.0f) || c <= 0.0f || c >= 1.0f;
}

// Where x lies across cut c's window, 0 below it to 1 above it (the window not a step).
CANOPY_FN float lod_window_position(float x, float c, int window, float width) {
    float w = lod_window_half_width(c, window, width);
    return clamp((x - (lod_window_top(c, w) - 2.0f * w)) / (2.0f * w), 0.0f, 1.0f);
}

// The share of a blade at x = bdth / ld that lies beyond cut c, i.e. that the farther of the two
// representations meeting at c draws: [x > c] for the binary cut, else a ramp over the window
// (linear or smoothstep). 1 - lod_beyond(x, c) is Algorithm 1's opacity (lod_far_opacity: the
// slices' in Boulanger's order) and Lemme's opacity_s (eq 5.26) with canopy's centred window.
CANOPY_FN float lod_beyond(float x, float c, int window, float width) {
    if (lod_cut_is_step(c, window, width)) return x > c ? 1.0f : 0.0f;
    float t = lod_window_position(x, c, window, width);
    return window == GRASS_LOD_WINDOW_LINEAR ? t : t * t * (3.0f - 2.0f * t);
}

// The mean of lod_beyond(., c) over thresholds spread evenly over [a, b] (x units, a <= b): the
// window's ramp and the part above it integrated apart, so that a narrow range (a filtered lookup
// between a level-0 texel and the next) keeps its precision; a range under 1e-4 wide reads its
// middle.
CANOPY_FN float lod_beyond_mean(float a, float b, float c, int window, float width) {
    if (!(b - a > 1.0e-4f)) return lod_beyond(0.5f * (a + b), c, window, width);
    if (lod_cut_is_step(c, window, width)) return (max(b, c) - max(a, c)) / (b - a);
    float w = lod_window_half_width(c, window, width);
    float top = lod_window_top(c, w);
    float ta = lod_window_position(a, c, window, width);
    float tb = lod_window_position(b, c, window, width);
    // The ramp's integral over the window, 2w times that of t (linear) or of 3t^2 - 2t^3 (smoothstep).
    float ramp = window == GRASS_LOD_WINDOW_LINEAR ? 0.5f * (tb - ta) * (tb + ta)
                                                   : (tb * tb * tb - ta * ta * ta) - 0.5f * (tb * tb * tb * tb - ta * ta * ta * ta);
    return (2.0f * w * ramp + (max(b, top) - max(a, top))) / (b - a);
}

// Which of a pixel's screen-door values h in [0, 1) (lod_screen_door) draw a blade at x = bdth / ld
// in the band (lo, hi]: [1 - beyond(lo), 1 - beyond(hi)). The bands' intervals tile [0, 1) near to
// far without gap or overlap, so two representations sharing a blade draw complementary pixels
// of it and their shares sum to 1; a thinned blade (x > 1) or no grass (ld = 0) gets none. The
// binary cut gives [0, 1) or nothing: grass_blade_in_band.
CANOPY_FN vec2 lod_band_interval(float bdth, float ld, vec2 band, int window, float width) {
    if (!(ld > 0.0f) || !(bdth > 0.0f) || bdth > ld) return vec2(0.0f, 0.0f);
    float x = bdth / ld;
    return vec2(1.0f - lod_beyond(x, band.x, window, width), 1.0f - lod_beyond(x, band.y, window, width));
}

// A per-pixel value in [0, 1) that every representation reads alike at a pixel: canopy's screen
// door for a blade's share in a band, so a transition's two shares of one blade land on
// complementary pixels (a shared alpha through alpha-to-coverage would cover the same samples
// twice). An 8 x 8 ordered-dither (Bayer) matrix in integer arithmetic, so every shader and the
// C++ tests compute the same value bit for bit; any 8 x 8 pixels hold each of its 64 levels once.
CANOPY_FN float lod_screen_door(vec2 pixel) {
    uint x = uint(max(floor(pixel.x), 0.0f)) & 7u;
    uint y = uint(max(floor(pixel.y), 0.0f)) & 7u;
    uint xy = x ^ y;
    uint level = ((xy & 1u) << 5u) | ((y & 1u) << 4u) | ((xy & 2u) << 2u) | ((y & 2u) << 1u) | ((xy & 4u) >> 1u) |
                 ((y & 4u) >> 2u);
    return (float(level) + 0.5f) / 64.0f;
}

// Whether screen-door value h falls in `interval`.
CANOPY_FN bool lod_interval_draws(vec2 interval, float h) { return h >= interval.x && h < interval.y; }

// grass.lod's three representations, near to far.
CANOPY_CONST int GRASS_LOD_GEOMETRY = 0;
CANOPY_CONST int GRASS_LOD_VOLUME = 1;
CANOPY_CONST int GRASS_LOD_IMAGE = 2;

// 1 up to a, 0 from b, linear between: eq 4.3's form, lod_weight_geometry(d, a, b), and a step
// at b where a = b (eq 4.3 would divide by zero there).
CANOPY_FN float lod_ramp_down(float d, float a, float b) {
    if (!(b > a)) return d < b ? 1.0f : 0.0f;
    return clamp((b - d) / (b - a), 0.0f, 1.0f);
}

// grass.lod's cuts c1 <= c2 of a cell's thresholds at distance d (canopy's reading of Boulanger
// eq 4.3-4.5 with Lemme's binary test, eq 5.25 made complementary): the geometry keeps the blades
// with bdth in (0, c1 ld], the volume (c1 ld, c2 ld], the image (c2 ld, ld]. c1 = w_g (eq 4.3),
// 1 - c2 is the image's weight, rising over [image_start, image_full], and c2 - c1 is w_vs
// (eq 4.4) where the two transitions do not overlap. The three bands partition ]0, ld] for any
// d, so no blade is drawn twice or dropped. Boulanger draws the horizontal slice at 1 - w_g,
// beneath the vertical slices too (eq 4.5): with opaque volume texels that would draw the
// volume's blades a second time, so canopy's image keeps only what the volume leaves.
CANOPY_FN vec2 lod_cuts(float d, float geometry_full, float geometry_none, float image_start, float image_full) {
    float c1 = lod_ramp_down(d, geometry_full, geometry_none);
    float c2 = max(c1, lod_ramp_down(d, image_start, image_full));
    return vec2(c1, c2);
}

// The share (lo, hi] of ]0, 1] a representation draws, in units of the local density
// (grass_blade_in_band, grass_density.h).
CANOPY_FN vec2 lod_band(int representation, vec2 cuts) {
    if (representation == GRASS_LOD_GEOMETRY) return vec2(0.0f, cuts.x);
    if (representation == GRASS_LOD_VOLUME) return vec2(cuts.x, cuts.y);
    return vec2(cuts.y, 1.0f);
}

// Lemme's volume levels (his football field, L930-935: 8, 2 and 1 slices a direction between the
// blades and the image): the volume's band (c1, c2] is split among up to three levels, each
// handing its blades to the next over a ramp of its own, as the bands hand theirs: level 1 keeps
// (c1, m1], level 2 (m1, m2], level 3 (m2, c2], with m1 = max(c1, ramp_down(d, ramps.x, ramps.y))
// and m2 = max(m1, ramp_down(d, ramps.z, ramps.w)), both at most c2. `ramps`: where level 2 takes
// over from level 1 (start, full) and level 3 from level 2. A level not used has its ramp at
// LOD_NO_DISTANCE (lod_volume_ramps): its band is empty, and the one volume level keeps (c1, c2]
// as lod_band does. In order (ramps.x <= ramps.y <= ramps.z <= ramps.w <= image_start), the five
// bands partition ]0, 1] for any d.
CANOPY_CONST float LOD_NO_DISTANCE = 3.0e38f;
CANOPY_FN vec2 lod_volume_level_band(int level, vec2 cuts, float d, vec4 ramps) {
    float m1 = min(cuts.y, max(cuts.x, lod_ramp_down(d, ramps.x, ramps.y)));
    float m2 = min(cuts.y, max(m1, lod_ramp_down(d, ramps.z, ramps.w)));
    if (level <= 1) return vec2(cuts.x, m1);
    if (level == 2) return vec2(m1, m2);
    return vec2(m2, cuts.y);
}

// What one volume level's pass reads (std140, a uniform at binding 7): x, its level (1 to 3);
// y, its slices a direction; z, 1 in grass.lod's hilltop pass, which draws the image's band of
// its cells' blades again with that level's slices (Lemme §6.4.6), else 0; w: 0.
struct GrassLodVolumeLevel {
    ivec4 level_slices;
};

// The level ramps of `levels` volume levels (1 to 3): the unused levels' at LOD_NO_DISTANCE.
CANOPY_FN vec4 lod_volume_ramps(int levels, float level2_start, float level2_full, float level3_start, float level3_full) {
    vec4 none = vec4(LOD_NO_DISTANCE, LOD_NO_DISTANCE, LOD_NO_DISTANCE, LOD_NO_DISTANCE);
    if (levels <= 1) return none;
    if (levels == 2) return vec4(level2_start, level2_full, LOD_NO_DISTANCE, LOD_NO_DISTANCE);
    return vec4(level2_start, level2_full, level3_start, level3_full);
}

// The distances of a cell's centre beyond which a representation's band is empty, whatever the
// thresholds (lo, hi; hi = LOD_NO_DISTANCE: none): the geometry's to geometry_none, the volume's
// from geometry_full to image_full, the image's from image_start (c2 < 1 only past image_start).
// grass.lod culls each band's copies to these, so no pass draws a cell whose share is nothing.
CANOPY_FN vec2 lod_band_distances(int representation, float geometry_full, float geometry_none, float image_start,
                                  float image_full) {
    if (representation == GRASS_LOD_GEOMETRY) return vec2(0.0f, geometry_none);
    if (representation == GRASS_LOD_VOLUME) return vec2(geometry_full, image_full);
    return vec2(image_start, LOD_NO_DISTANCE);
}

// The same for volume level 1 to 3 (lod_volume_level_band): level 1 draws from geometry_full,
// level k > 1 from its ramp's start; each until the next level's ramp is full or the image's is.
CANOPY_FN vec2 lod_volume_level_distances(int level, vec4 ramps, float geometry_full, float image_full) {
    if (level <= 1) return vec2(geometry_full, min(ramps.y, image_full));
    if (level == 2) return vec2(ramps.x, min(ramps.w, image_full));
    return vec2(ramps.z, image_full);
}

CANOPY_END_NAMESPACE

#endif
