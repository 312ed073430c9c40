// The share of a blade's thresholds a representation's shader draws (lod_band, lod_selection.h):
// all of them (0, 1] when compiled alone; inside grass.lod, whose shaders define
// GRASS_LOD_REPRESENTATION before including their representation's body, the band of that
// representation at the blade's distance. With transition_distance = "blade" (the default, both
// theses) the distance is the eye's to the blade's root on its copy's ground (patch point
// (root.x, 0, root.z) placed as the copy is): the blades read their root attribute, the
// image-based representations the root their blade map holds (a filtered texel's blades' mean);
// with "cell", to the cell's centre (patch point (0.5, 0, 0.5), which mirroring keeps). Every
// representation places the point alike, so they agree on the cut of every blade. Needs
// frame_uniforms.glsl and, in grass.lod, GrassLodParams as the technique's block.
//
// grass.lod's volume shaders define GRASS_LOD_VOLUME_LEVELS: one pass per volume level (Lemme's
// 8, 2 and 1 slices), each with its level and slice count in a uniform at binding 7
// (GrassLodVolumeLevel), draws that level's share of the volume's band (lod_volume_level_band);
// the hilltop pass (its z set) draws the image's band instead.
#ifndef CANOPY_GRASS_LOD_BAND_GLSL
#define CANOPY_GRASS_LOD_BAND_GLSL
#include "grass_macro_cells.h"
#include "lod_selection.h"

#ifdef GRASS_LOD_VOLUME_LEVELS
layout(set = 0, binding = 7, std140) uniform LodLevelBlock { GrassLodVolumeLevel lod_level; };
#define GRASS_VOLUME_SLICES (lod_level.level_slices.y)
#endif

// The band of a cell whose centre is `centre` (world).
vec2 grass_representation_band_at(vec3 centre) {
#ifdef GRASS_LOD_REPRESENTATION
    float d = distance(centre, frame.camera_position.xyz);
    vec2 cuts = lod_cuts(d, frame.technique.geometry_full, frame.technique.geometry_none, frame.technique.image_start,
                         frame.technique.image_full);
#ifdef GRASS_LOD_VOLUME_LEVELS
    // The hilltop pass: the image's blades, drawn again as vertical slices (Lemme §6.4.6).
    if (lod_level.level_slices.z != 0) return lod_band(GRASS_LOD_IMAGE, cuts);
    vec4 ramps = lod_volume_ramps(frame.technique.volume_levels, frame.technique.volume_2_start,
                                  frame.technique.volume_2_full, frame.technique.volume_3_start,
                                  frame.technique.volume_3_full);
    return lod_volume_level_band(lod_level.level_slices.x, cuts, d, ramps);
#else
    return lod_band(GRASS_LOD_REPRESENTATION, cuts);
#endif
#else
    return vec2(0.0, 1.0);
#endif
}

// The window a blade crosses a cut over (lod_band_interval): grass.lod's `transition`; binary
// where a representation draws alone (its band is all the blades).
int grass_transition_window() {
#ifdef GRASS_LOD_REPRESENTATION
    return frame.technique.transition_window;
#else
    return GRASS_LOD_WINDOW_BINARY;
#endif
}
float grass_transition_width() {
#ifdef GRASS_LOD_REPRESENTATION
    return frame.technique.transition_width;
#else
    return 0.0;
#endif
}

// The patch point whose distance decides a blade's band: its root (x, z), or the cell's centre.
vec2 grass_band_point(vec2 root) {
#ifdef GRASS_LOD_REPRESENTATION
    if (frame.technique.transition_distance == GRASS_LOD_DISTANCE_CELL) return vec2(0.5);
#endif
    return root;
}

// The band of a blade rooted at patch point `root` of the copy placed by `model`.
vec2 grass_blade_band(mat4 model, vec2 root) {
    vec2 p = grass_band_point(root);
    return grass_representation_band_at((model * vec4(p.x, 0.0, p.y, 1.0)).xyz);
}

// The same for a blade of field cell `cell` of the macro-cells' field (grass_macro_cells.h),
// placed from the field instead of a copy's matrix: the cell mirrored by its signs `s`, lifted by
// `ground`, the height of its first grid vertex above the field's origin, as a copy's model lifts
// the cell on a terrain (grass_terrain.h); 0 on flat ground.
vec2 grass_macro_blade_band(GrassMacroField field, ivec2 cell, vec2 s, float ground, vec2 root) {
    vec2 p = grass_band_point(root);
    vec2 placed = vec2(s.x < 0.0 ? 1.0 - p.x : p.x, s.y < 0.0 ? 1.0 - p.y : p.y);
    return grass_representation_band_at(field.origin_size.xyz + vec3(0.0, ground, 0.0) +
                                         vec3(float(cell.x) + placed.x, 0.0, float(cell.y) + placed.y) * field.origin_size.w);
}
#endif
