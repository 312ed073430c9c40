// The local density a blade is thinned by (Lemme §4.1.3 and eq 5.22, Boulanger §4.3.1): the
// field's density map is read at the four corners of each cell, and a blade's density is the
// bilinear blend of those four at its root. canopy's choice (the theses sample the map per
// blade, in a texture): the four corner values are per-copy data, so the blade draw, the
// reference's ray filter and every other representation thin exactly the same blades without
// a texture fetch per vertex. The corners are given in the patch's own coordinates, i.e. already
// permuted by the cell's mirror (grass_patch_corner_densities). GLSL and C++ (shared_math.h).
#ifndef CANOPY_GRASS_DENSITY_H
#define CANOPY_GRASS_DENSITY_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// corners: the density at patch points (0, 0), (1, 0), (0, 1), (1, 1) in x and z; root_xz: the
// blade's root in the patch, [0, 1]^2.
CANOPY_FN float grass_root_density(vec4 corners, vec2 root_xz) {
    vec2 f = clamp(root_xz, vec2(0.0f), vec2(1.0f));
    float near_edge = corners.x + (corners.y - corners.x) * f.x;  // z = 0
    float far_edge = corners.z + (corners.w - corners.z) * f.x;   // z = 1
    return near_edge + (far_edge - near_edge) * f.y;
}

// Kept when the density reaches the threshold (Lemme eq 5.22: bdth <= ld); thresholds lie in
// ]0, 1], so density 0 draws nothing and density 1 every blade.
CANOPY_FN bool grass_blade_drawn(float threshold, float density) { return threshold <= density; }

// Kept by a representation that draws the share band = (lo, hi] of the blades the density keeps
// (grass.lod: lod_band, lod_selection.h): bdth in (lo ld, hi ld]. The band (0, 1] is
// grass_blade_drawn (thresholds are > 0), and the three bands of grass.lod draw each blade once.
CANOPY_FN bool grass_blade_in_band(float threshold, float density, vec2 band) {
    return threshold > band.x * density && threshold <= band.y * density;
}

// The cell's corner densities in world order (x0z0, x1z0, x0z1, x1z1) turned into the patch's
// order for mirror signs s (cell_mirroring.h): a mirrored axis swaps its two ends.
CANOPY_FN vec4 grass_patch_corner_densities(vec4 world, vec2 s) {
    vec4 c = world;
    if (s.x < 0.0f) c = vec4(c.y, c.x, c.w, c.z);
    if (s.y < 0.0f) c = vec4(c.z, c.w, c.x, c.y);
    return c;
}

CANOPY_END_NAMESPACE

#endif
