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

// A smooth alpha for alpha-to-coverage: the fraction of the pixel's footprint across the strip
// that lies inside the outline (a box filter). The footprint is f = `u_filter_width` wide
// (fwidth(uv.x) in a fragment shader), centred at u and slid to lie within the strip [0, 1]
// (the samples that reach a fragment all lie on the strip); from f >= 1 on it is the whole
// strip, so on a strip narrower than a pixel the alpha is the outline's share of the strip's
// width, 2 w(v), and the samples the strip covers carry the outline's true coverage. Where the
// footprint fits inside the strip and inside the outline's width, it is 0.5 on the edge and
// >= 0.5 exactly where blade_opaque is. A filter width of 0 (or NaN) is the hard test.
CANOPY_FN float blade_alpha(vec2 uv, float taper, float u_filter_width) {
    float w = blade_half_width(uv.y, taper);
    if (!(u_filter_width > 0.0f)) return abs(uv.x - 0.5f) <= w ? 1.0f : 0.0f;
    float span = min(u_filter_width, 1.0f);
    float lo = clamp(uv.x - 0.5f * span, 0.0f, 1.0f - span);
    float covered = max(min(lo + span, 0.5f + w) - max(lo, 0.5f - w), 0.0f);
    return clamp(covered / span, 0.0f, 1.0f);
}
// The fraction of the strip the outline covers: the integral of 2 w(v) over [0, 1].
CANOPY_FN float blade_coverage(float taper) { return taper / (taper + 1.0f); }

CANOPY_END_NAMESPACE

#endif
