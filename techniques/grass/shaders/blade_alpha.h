// A blade's outline (Lemme L325: "The alpha mask of this texture determines the final shape";
// Boulanger Fig 4.4): the strip is a rectangle in (u, v), u across, v from root to tip, and the
// mask keeps |u - 1/2| <= w(v) = (1 - v^k) / 2, full width at the root, a point at the tip; k
// (the taper exponent) sets how long the blade stays wide. Procedural, so the raster and the
// Embree reference cut the same outline; GLSL and C++ (shared_math.h).
#ifndef CANOPY_GRASS_BLADE_ALPHA_H
#define CANOPY_GRASS_BLADE_ALPHA_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

CANOPY_FN float blade_half_width(float v, float taper) {
    return 0.5f * (1.0f - pow(clamp(v, 0.0f, 1.0f), taper));
}

// The alpha test (and the reference's ray filter): inside the outline.
CANOPY_FN bool blade_opaque(vec2 uv, float taper) { return abs(uv.x - 0.5f) <= blade_half_width(uv.y, taper); }

// A smooth alpha for alpha-to-coverage: the outline's edge ramped over `u_filter_width` (a
// pixel's extent in u, fwidth(uv.x) in a fragment shader); 0.5 on the edge, so alpha >= 0.5
// is exactly blade_opaque, and a filter width of 0 gives the hard test.
CANOPY_FN float blade_alpha(vec2 uv, float taper, float u_filter_width) {
    float inside = blade_half_width(uv.y, taper) - abs(uv.x - 0.5f);
    return clamp(inside / max(u_filter_width, 1e-6f) + 0.5f, 0.0f, 1.0f);
}

// The fraction of the strip the outline covers: the integral of 2 w(v) over [0, 1].
CANOPY_FN float blade_coverage(float taper) { return taper / (taper + 1.0f); }

CANOPY_END_NAMESPACE

#endif
