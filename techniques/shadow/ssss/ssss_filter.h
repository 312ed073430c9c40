// Screen-space soft shadows (Gumbau 2011, ch. 6): the math of the coarse map's dilation (6.2.1),
// the Gaussian's width (eq 6.2, 6.2.3), the blur's taps, its depth-discontinuity test and lazy
// shadowing (6.3.2), shared by the GLSL passes and the C++ tests (shared_math.h), so the tests
// check the code the GPU runs. Distances are world units along the light's axis (d_blocker,
// d_receiver) or from the camera (d_observer); offsets and widths in pixels or texels as named.
#ifndef CANOPY_SSSS_FILTER_H
#define CANOPY_SSSS_FILTER_H

#include "../shaders/shadow_filtering.h"

CANOPY_BEGIN_NAMESPACE

// A Gaussian-blurred step rises from 10 % to 90 % over 2 x 1.2816 = 2.563 sigma: that rise is
// made the penumbra width of eq 6.2.
CANOPY_CONST float SSSS_PENUMBRA_WIDTH_IN_SIGMAS = 2.563f;

// Below this sigma (pixels) a Gaussian changes nothing visible: the pixel is not blurred.
CANOPY_CONST float SSSS_MIN_SIGMA = 0.25f;

// Eq 6.2 as the Gaussian's sigma in pixels: w = (d_r - d_b) w_light / (d_b Z) is a width per
// unit of depth; times the focal length in pixels it is pixels, and divided by 2.563 the sigma
// whose 10-90 % rise spans it. Z is the paper's "distance of the observer to the point (Z)"
// (MRT3), taken as the receiver's depth along the camera's axis: the perspective divides by it,
// so a width w at depth Z spans w f / Z pixels anywhere in the image. (The Euclidean distance
// would draw penumbrae off the view axis narrower by the cosine of their angle to the axis.)
CANOPY_FN float ssss_sigma_pixels(float d_receiver, float d_blocker, float w_light, float view_depth, float focal_pixels) {
    return ssss_screen_penumbra_width(d_receiver, d_blocker, w_light, view_depth) * max(focal_pixels, 0.0f) /
           SSSS_PENUMBRA_WIDTH_IN_SIGMAS;
}

// The anisotropic kernel's axes (canopy's separable stand-in for Geusebroek's, see the README): a
// disk on the tangent plane projects to an ellipse whose screen x and y extents shrink by
// sqrt(1 - n_x^2) and sqrt(1 - n_y^2), n the unit view-space normal.
CANOPY_FN vec2 ssss_anisotropic_sigma(float sigma, vec3 view_normal) {
    return sigma * vec2(sqrt(max(1.0f - view_normal.x * view_normal.x, 0.0f)),
                        sqrt(max(1.0f - view_normal.y * view_normal.y, 0.0f)));
}

// ---------------------------------------------------------------------------------------------
// Dilation of the coarse map (6.2.1, L1614): "proportional to the size of the area light", times
// the user's constant, "the maximum distance to the occluder in the scene". A blocker at
// d_blocker shadows receivers up to max_distance behind it (but not past the far plane). The blur
// spreads its hard-shadow edge over the Gaussian's support, +-3 sigma = +-(3 / 2.563) w with w
// eq 6.1's width (w_light (d_r - d_b) / d_b on the receiver): every receiver that far beyond the
// edge must find the blocker in the coarse map, or it is left unblurred and the penumbra stops
// with a step (the paper's "penumbrae will not be completely smooth"). In shadow texels at the
// receiver (a texel spans texel_world, times d_r for a perspective map):
//   perspective: (3 / 2.563) w_light (1 / d_b - 1 / d_r) / texel_world;  orthographic: / texel_world.
// Proportional to w_light (G-F6.9), 0 for a point light, and larger for blockers nearer the light.
CANOPY_CONST float SSSS_DILATION_IN_WIDTHS = 3.0f / SSSS_PENUMBRA_WIDTH_IN_SIGMAS;

CANOPY_FN float ssss_dilation_texels(float d_blocker, float max_distance, float far_plane, float w_light,
                                     float texel_world, bool perspective) {
    float d_b = max(d_blocker, 1e-6f);
    float d_r = max(min(d_b + max(max_distance, 0.0f), far_plane), d_b);
    float spread = SSSS_DILATION_IN_WIDTHS * clamp(w_light, 0.0f, 1e20f) * (d_r - d_b) / d_b;  // world units at the receiver
    return min(spread / (max(texel_world, 1e-20f) * (perspective ? d_r : 1.0f)), 1e30f);  // finite for any input
}

// Whether a coarse texel `offset` coarse texels away (block x block shadow texels each) is within
// `reach` shadow texels: the gap between the two texels' facing edges, (|offset| - 1) block, is
// below it. Its own texel always is.
CANOPY_FN bool ssss_dilation_reaches(int offset, float reach, int block) {
    return offset == 0 || float((abs(offset) - 1) * block) < reach;
}

// The coarse texel under a shadow-map texel: coarse texel i is the minimum of shadow texels
// [i block, (i + 1) block) in each axis (block_min.comp; the last block may be partial).
CANOPY_FN ivec2 ssss_coarse_texel(ivec2 shadow_texel, int block, ivec2 coarse_size) {
    return clamp(shadow_texel / max(block, 1), ivec2(0), coarse_size - ivec2(1));
}

// ---------------------------------------------------------------------------------------------
// The blur (6.2.3): `taps` samples over +-3 sigma, each on a whole pixel. Taps are spaced
// 6 sigma / (taps - 1) apart but at least one pixel, so no pixel is sampled twice (a narrow
// Gaussian is then sampled at every pixel of +-(taps - 1) / 2 instead of repeating the centre),
// and rounded half away from zero, so the kernel is symmetric. Each weight is the Gaussian of the
// tap's actual offset: the kernel is a Gaussian sampled at the pixels it reads, normalised by the
// sum of the weights used. Offsets are clamped to +-1e6 pixels (beyond any image; fetches clamp to
// the edge), so a huge sigma (eq 6.2 near d_blocker = 0) cannot overflow the int.
CANOPY_FN int ssss_tap_offset(int i, int taps, float sigma) {
    // Spacing capped (an infinite sigma would make the centre tap 0 * inf = NaN).
    float spacing = taps > 1 ? clamp(6.0f * sigma / float(taps - 1), 1.0f, 2e6f) : 0.0f;
    float offset = clamp((float(i) - 0.5f * float(taps - 1)) * spacing, -1e6f, 1e6f);
    return int(sign(offset) * floor(abs(offset) + 0.5f));
}

CANOPY_FN float ssss_tap_weight(int offset, float sigma) {
    float x = float(offset) / max(sigma, 1e-6f);
    return exp(-0.5f * x * x);
}

// Pixels the blur leaves as they are (the mask of 6.2.2): sigma below SSSS_MIN_SIGMA (the screen
// pass writes 0 where the coarse map finds no blocker: no penumbra can reach the pixel), and the
// background (distance 1e30).
CANOPY_FN bool ssss_blurs(float sigma, float distance) {
    return sigma >= SSSS_MIN_SIGMA && distance <= 1e29f;
}

// The centre pixel's tangent plane (normal n through the centre point, given relative to the
// camera): the distance along a unit view ray at which the ray meets it, or -1 when the ray misses
// it (grazing, behind the camera, or beyond 1e30, the background's distance; NaN inputs too).
// Lazy shadowing (6.3.2) shadow-tests hidden taps there, and the depth test below expects visible
// taps of the centre's surface there.
CANOPY_FN float ssss_tangent_plane_distance(vec3 n, vec3 ray, vec3 centre_from_camera) {
    float facing = dot(n, ray);
    if (!(abs(facing) >= 1e-4f)) return -1.0f;
    float t = dot(n, centre_from_camera) / facing;
    return t > 0.0f && t < 1e30f ? t : -1.0f;
}

// Where a tap of the centre's surface should be: the distance at which the tap's view ray meets
// the centre's tangent plane (the paper's local planarity, 6.3.2), or, where the ray misses the
// plane, the centre's own distance. On a flat floor seen from close by the distance to the
// observer changes by several per cent within a wide kernel, so comparing with the centre's
// distance (Algorithm 4's |z_tap - z_ref|) would drop taps of the very surface being blurred.
CANOPY_FN float ssss_expected_distance(vec3 n, vec3 tap_ray, vec3 centre_from_camera, float centre_distance) {
    float t = ssss_tangent_plane_distance(n, tap_ray, centre_from_camera);
    return t > 0.0f ? t : centre_distance;
}

// A tap belongs to the centre's surface when its distance to the observer differs from the
// expected one (ssss_expected_distance) by at most depth_error of it; others are dropped or, with
// lazy shadowing, re-evaluated (6.2.3, Alg. 4). Infinite or NaN distances are another surface.
CANOPY_FN bool ssss_same_surface(float tap_distance, float expected_distance, float depth_error) {
    return abs(tap_distance - expected_distance) <= depth_error * min(expected_distance, 1e30f);
}

CANOPY_END_NAMESPACE

#endif
