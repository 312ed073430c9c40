// A height field's surface between four grid vertices, as its mesh triangulates it: the quad's
// (1, 0)-(0, 1) diagonal splits it into the triangles (v00, v01, v10), where fx + fz <= 1, and
// (v11, v10, v01). Anything standing on the terrain (grass roots, Lemme eq 6.13) reads the
// height here, so it stands on the very triangles the ground is drawn and ray-traced with,
// rather than on a bilinear blend that floats above or sinks below them. GLSL and C++
// (shared_math.h).
#ifndef CANOPY_HEIGHT_FIELD_H
#define CANOPY_HEIGHT_FIELD_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// h: the heights at (0, 0), (1, 0), (0, 1), (1, 1) in x and z; f: the point in the quad, [0, 1]^2.
CANOPY_FN float height_field_quad(vec4 h, vec2 f) {
    if (f.x + f.y <= 1.0f) return h.x + f.x * (h.y - h.x) + f.y * (h.z - h.x);
    return h.w + (1.0f - f.x) * (h.z - h.w) + (1.0f - f.y) * (h.y - h.w);
}

CANOPY_END_NAMESPACE

#endif
