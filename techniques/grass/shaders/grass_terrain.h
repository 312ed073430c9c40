// Grass on a terrain (Lemme §6.4.4, eq 6.13: each blade moved up by the height under its root).
// canopy's choice: the terrain's grid is the field's cells, one grid quad a cell, so a cell's
// ground is its four corner heights (harness/shaders/height_field.h's two triangles), and the
// raster and the reference lift exactly the same blades by exactly the same heights without a
// height-map fetch per vertex. A copy's model lifts the cell to its (x0, z0) corner; the three
// other corners' heights above that one ride in the w of its normal matrix's columns (unused by
// the 3 x 3 normal transform), in world order: (x1, z0), (x0, z1), (x1, z1). GLSL and C++.
#ifndef CANOPY_GRASS_TERRAIN_H
#define CANOPY_GRASS_TERRAIN_H

#include "height_field.h"

CANOPY_BEGIN_NAMESPACE

// A patch point's place in its cell in world x and z, [0, 1]^2: the patch mirrored by the cell's
// signs (cell_mirroring.h; the model's x and z scales carry them).
CANOPY_FN vec2 grass_cell_point(vec2 patch_xz, vec2 mirror_signs) {
    return vec2(mirror_signs.x > 0.0f ? patch_xz.x : 1.0f - patch_xz.x,
                mirror_signs.y > 0.0f ? patch_xz.y : 1.0f - patch_xz.y);
}

// How far above its cell's (x0, z0) corner the ground under a blade's root lies, world units;
// lift = the normal matrix's w components (0 on flat ground).
CANOPY_FN float grass_terrain_lift(vec3 lift, vec2 root_patch_xz, vec2 mirror_signs) {
    return height_field_quad(vec4(0.0f, lift.x, lift.y, lift.z), grass_cell_point(root_patch_xz, mirror_signs));
}

// Where the ground's diagonal (its two triangles meet along world-order cell points with
// x + z = 1, height_field.h) crosses a vertical plane of the patch: the plane x = `plane` (axis 0)
// or z = `plane` (axis 1), in patch space; returns the other patch coordinate of the crossing. A
// vertical slice cut there lies over one ground triangle on each side, so lifting its vertices
// follows the ground exactly.
CANOPY_FN float grass_diagonal_crossing(int axis, float plane, vec2 mirror_signs) {
    if (axis == 0) {
        float cell_x = mirror_signs.x > 0.0f ? plane : 1.0f - plane;
        return mirror_signs.y > 0.0f ? 1.0f - cell_x : cell_x;
    }
    float cell_z = mirror_signs.y > 0.0f ? plane : 1.0f - plane;
    return mirror_signs.x > 0.0f ? 1.0f - cell_z : cell_z;
}

CANOPY_END_NAMESPACE

#endif
