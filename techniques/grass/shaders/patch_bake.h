// How grass techniques bake their patch at load (GLSL and C++): an orthographic camera framing
// the prototype's bounds (or, tiled, its cell) along one axis (common/patch_bake.hpp makes them).
// One struct for the bake passes' uniform block and the C++ that fills it. What a baked texel
// holds: blade_texels.h.
#ifndef CANOPY_GRASS_PATCH_BAKE_H
#define CANOPY_GRASS_PATCH_BAKE_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

struct PatchBake {
    mat4 view_proj;      // patch space -> the bake's clip space
    vec4 toward_viewer;  // unit: the side of a two-sided blade the bake sees (the axis it looks along)
    vec4 section;        // x, y: a slice's bake keeps what lies in [x, y) along toward_viewer
    // x: 0, the patch alone (framing its bounds); 1, the patch and its 8 neighbours, drawn as
    // instances 0-8 (patch_bake_tile), framing the cell: a bake that tiles (Boulanger §4.2.3).
    vec4 tiles;
};

// Where instance `instance` of a tiled bake puts the patch: one of the 3 x 3 cells around it.
CANOPY_FN vec3 patch_bake_tile(int instance) {
    return vec3(float(instance % 3 - 1), 0.0f, float(instance / 3 - 1));
}

// Whether patch point `p` lies in the bake's section (between Lemme's two clipping planes, §4.2.1).
CANOPY_FN bool patch_bake_keeps(PatchBake bake, vec3 p) {
    float along = dot(p, vec3(bake.toward_viewer));
    return along >= bake.section.x && along < bake.section.y;
}

CANOPY_END_NAMESPACE

#endif
