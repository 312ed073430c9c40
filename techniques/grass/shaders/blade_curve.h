// A grass blade's spine (Lemme 2012, eq 4.1-4.2): a particle launched from the root with
// velocity b under gravity g, p(t) = b t + g t^2, sampled at equal steps of t in [0, 1] (the
// thesis gives no range of t: canopy's choice, so the tip is at b + g). Compiles as GLSL and as
// C++ (shared_math.h), so the tests check the code a blade shader runs.
#ifndef CANOPY_GRASS_BLADE_CURVE_H
#define CANOPY_GRASS_BLADE_CURVE_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// The spine point at parameter t, relative to the root (eq 4.1).
CANOPY_FN vec3 blade_point(vec3 b, vec3 g, float t) { return b * t + g * (t * t); }

// Its derivative (eq 4.2): the blade's direction at t. Normals are orthogonal to it.
CANOPY_FN vec3 blade_tangent(vec3 b, vec3 g, float t) { return b + g * (2.0f * t); }

// The largest downward pull that keeps the tip no lower than any point before it: the spine's
// height b.y t - pull t^2 rises on [0, 1] while pull <= b.y / 2, and then |v| shrinks from root
// to tip, so the triangles get smaller towards the tip as Lemme L321 says. Past it the blade
// would droop below its apex, which the thesis's blades do not.
CANOPY_FN float blade_max_pull(float rise) { return 0.5f * rise; }

CANOPY_END_NAMESPACE

#endif
