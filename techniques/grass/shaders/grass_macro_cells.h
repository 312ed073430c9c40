// Lemme's macro-cells (§6.2, Boulanger B L1052): one quad or cuboid over k x k cells of the field,
// each of its cells shown by texture repetition (eq 6.6), mirrored and thinned as that cell's own
// copy is. A macro-cell reads its cells' mirror signs and corner densities from a storage buffer
// (GrassCell, one per field cell in the population's copy order), so a field costs O(cells)
// whatever its macro size. GLSL and C++ (shared_math.h): the unit tests check these functions.
#ifndef CANOPY_GRASS_MACRO_CELLS_H
#define CANOPY_GRASS_MACRO_CELLS_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// One field cell as a macro-cell reads it (std430: 32 bytes).
struct GrassCell {
    vec4 densities;  // the cell's corner densities in patch order (grass_density.h)
    vec4 signs;      // xy: the cell's mirror signs (cell_mirroring.h); zw: 0
};

// The field the macro-cells tile (std140).
struct GrassMacroField {
    vec4 origin_size;  // xyz: the corner of cell (0, 0), world; w: a cell's width, world
    ivec4 cells;       // x, y: cells along x and z (the shaders index field_cells by them); z: the macro size k, for a reader of the buffer (no shader needs it); w: 0
    vec4 patch_top;    // x: the patch's top (patch units, as the bake frames it); y: the population's transmission; zw: 0
};

// The field cell of macro-cell point u (field coordinates: one unit a cell) for the macro-cell
// whose first cell is `first` and that spans `span` cells: floor(u), kept inside the macro-cell
// so its far edges belong to its last cells.
CANOPY_FN ivec2 grass_macro_cell(vec2 u, ivec2 first, ivec2 span) {
    return clamp(ivec2(floor(u)), first, first + span - ivec2(1));
}

// The patch point (x and z in [0, 1]) that macro-cell point u shows in `cell` with mirror signs
// s: eq 6.6's fract(s u), written from the cell's own corner, so it holds on the cell's edges too
// (where fract would jump) and equals grass_mirror_slice_uv(u, s) - floor(u) inside the cell.
CANOPY_FN vec2 grass_macro_patch_point(vec2 u, ivec2 cell, vec2 s) {
    vec2 local = u - vec2(cell);
    return vec2(s.x < 0.0f ? 1.0f - local.x : local.x, s.y < 0.0f ? 1.0f - local.y : local.y);
}

// The slice a mirrored cell shows at its own slice plane `plane` (0 .. n-1 along one axis): the
// patch mirrored about its centre puts slice n-1-k where slice k was.
CANOPY_FN int grass_macro_slice(int plane, int n, float sign) { return sign < 0.0f ? n - 1 - plane : plane; }

// A patch-space vector (a baked normal) as a cell with mirror signs s shows it.
CANOPY_FN vec3 grass_mirror_vector(vec3 v, vec2 s) { return vec3(v.x * s.x, v.y, v.z * s.y); }

CANOPY_END_NAMESPACE

#endif
