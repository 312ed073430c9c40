// Aperiodic tiling of a grass field (Lemme 2012 eq 6.4-6.7; Boulanger 2008 B L837, L1058): every
// terrain cell shows the one patch, mirrored in x, in z, in both or in neither, chosen per cell,
// so the repetition does not show. Geometry is mirrored about the patch's centre (eq 6.7), slice
// textures through their coordinates (eq 6.6); both come from these functions, in GLSL and C++.
#ifndef CANOPY_GRASS_CELL_MIRRORING_H
#define CANOPY_GRASS_CELL_MIRRORING_H

#include "shared_math.h"

CANOPY_BEGIN_NAMESPACE

// PCG's output hash of one 32-bit word (Jarzynski and Olano 2020): the same bits in GLSL and C++.
CANOPY_FN uint grass_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

CANOPY_FN uint grass_cell_hash(ivec2 cell, uint seed) {
    return grass_hash(uint(cell.x) ^ grass_hash(uint(cell.y) ^ grass_hash(seed)));
}

// The cell's mirror signs, +-1 per axis (eq 6.4, s = 2 step(0.5, noise) - 1; Boulanger's
// orientation map holds the same two signs per cell). canopy's "noise" is the cell's hash: each
// of the four versions with probability 1/4, independent from cell to cell.
CANOPY_FN vec2 grass_mirror_signs(ivec2 cell, uint seed) {
    uint h = grass_cell_hash(cell, seed);
    return vec2((h & 1u) != 0u ? -1.0f : 1.0f, (h & 2u) != 0u ? -1.0f : 1.0f);
}

// A point of the patch (x and z in [0, 1]) mirrored about the patch's centre (eq 6.7).
CANOPY_FN vec3 grass_mirror_patch_point(vec3 p, vec2 s) {
    return vec3((p.x - 0.5f) * s.x + 0.5f, p.y, (p.z - 0.5f) * s.y + 0.5f);
}

// x - floor(x): Lemme's fract (App. A leaves it undefined); C's fmod would differ below zero.
CANOPY_FN float grass_fract(float x) { return x - floor(x); }

// Field coordinates (one unit a cell) to mirrored slice-texture coordinates (eq 6.6:
// u' = floor(u) + fract(s u)). The image of a point inside a cell is the eq 6.7 mirror of it;
// a cell's lower edge itself maps to itself with s = -1 (fract(-k) = 0), not to its upper edge.
CANOPY_FN vec2 grass_mirror_slice_uv(vec2 u, vec2 s) {
    return floor(u) + vec2(grass_fract(s.x * u.x), grass_fract(s.y * u.y));
}

CANOPY_END_NAMESPACE

#endif
