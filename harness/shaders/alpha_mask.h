// Procedural alpha masks cut into a population's prototype (Population::alpha_mask), written once
// for the GPU and the CPU: population.vert hands the mask and the prototype-space position to the
// fragment shader (population_alpha.glsl discards what is cut away), and the Embree reference
// lets its rays through at the same points (reference/embree_scene.cpp). The position is the
// prototype's mesh space, before its own transform and the copy's placement, so a mask moves,
// turns and scales with each copy.
// A mask is one vec4: x = kind (ALPHA_MASK_*), y = axis (0 x, 1 y, 2 z), z = period (> 0),
// w = opaque fraction of each period (in (0, 1]).
#ifndef CANOPY_ALPHA_MASK_H
#define CANOPY_ALPHA_MASK_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

CANOPY_CONST float ALPHA_MASK_NONE = 0.0f;     // opaque everywhere
CANOPY_CONST float ALPHA_MASK_STRIPES = 1.0f;  // slabs across the axis: opaque, then cut, each period

CANOPY_FN float alpha_mask_coordinate(vec4 mask, vec3 p) { return mask.y < 0.5f ? p.x : (mask.y < 1.5f ? p.y : p.z); }

// The period p lies in, an integer as a float (tests tell the mask's edges apart by it).
CANOPY_FN float alpha_mask_period_index(vec4 mask, vec3 p) { return floor(alpha_mask_coordinate(mask, p) / mask.z); }

// True where the surface stands, false where the mask cuts it away.
CANOPY_FN bool alpha_mask_opaque(vec4 mask, vec3 p) {
    if (mask.x < 0.5f) return true;
    float s = alpha_mask_coordinate(mask, p) / mask.z;
    return s - floor(s) < mask.w;
}

CANOPY_END_NAMESPACE

#endif
