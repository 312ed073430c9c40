// The share of a cell's blades a representation's shader draws (lod_band, lod_selection.h): all
// of them (0, 1] when compiled alone; inside grass.lod, whose shaders define
// GRASS_LOD_REPRESENTATION before including their representation's body, the band of that
// representation at the cell's distance. The distance is the eye's to the cell's centre (patch
// point (0.5, 0, 0.5), which mirroring keeps), computed per copy alike in every representation's
// vertex stage, so the three agree on the cuts of every cell. Needs frame_uniforms.glsl and, in
// grass.lod, GrassLodParams as the technique's block.
//
// grass.lod's volume shaders define GRASS_LOD_VOLUME_LEVELS: one pass per volume level (Lemme's
// 8, 2 and 1 slices), each with its level and slice count in a uniform at binding 7
// (GrassLodVolumeLevel), draws that level's share of the volume's band (lod_volume_level_band);
// the hilltop pass (its z set) draws the image's band instead.
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

// The band of the copy placed by `model`.
vec2 grass_representation_band(mat4 model) { return grass_representation_band_at((model * vec4(0.5, 0.0, 0.5, 1.0)).xyz); }

// The band of field cell `cell` of the macro-cells' field (grass_macro_cells.h): its centre is
// the same point, computed from the field's placement instead of a copy's matrix. `ground`: the
// height of the cell's first grid vertex above the field's origin, to which a copy's model lifts
// the cell on a terrain (grass_terrain.h); 0 on flat ground.
vec2 grass_macro_cell_band(GrassMacroField field, ivec2 cell, float ground) {
    return grass_representation_band_at(field.origin_size.xyz + vec3(0.0, ground, 0.0) +
                                         vec3(float(cell.x) + 0.5, 0.0, float(cell.y) + 0.5) * field.origin_size.w);
}
