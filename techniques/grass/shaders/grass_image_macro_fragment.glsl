// The image's fragment stage over macro-cells (grass.image with macro_cells, and grass.lod's far
// band under culling = "quadtree"; Lemme §6.2, eq 6.6): each point of the macro-cell's quad shows
// its own cell's copy of the tiled top view, filtered (its footprint taken from the macro-cell's
// coordinates, continuous across cells, not from the mirrored patch point, which jumps), mirrored
// by that cell's signs and cut by that cell's densities and, in grass.lod, by that cell's band
// (grass_lod_band.glsl), as the one-quad-per-cell path shows it; lit per pixel with the mirrored
// baked normal. Included after the technique's
// parameter block. With GRASS_MACRO_TERRAIN (a field on a terrain), a cell's band is taken at its
// centre lifted to its first corner's ground, where a copy's model puts it (grass_lod_band.glsl).
#include "frame_uniforms.glsl"
#include "grass_density.h"
#include "grass_macro_cells.h"
#include "grass_shading.glsl"
#include "grass_slice_coverage.glsl"
#include "grass_lod_band.glsl"

layout(set = 0, binding = 1) uniform sampler2DArray slice_albedo;  // trilinear, or NEAREST (mip_filter = "none")
layout(set = 0, binding = 2) uniform sampler2DArray slice_normal;  // the same
layout(set = 0, binding = 8) uniform sampler2DArray slice_blades;  // the same (blade_texels.h)
layout(set = 0, binding = 3, std140) uniform FieldBlock { GrassMacroField field; };
layout(set = 0, binding = 4, std430) readonly buffer CellBlock { GrassCell field_cells[]; };
#ifdef GRASS_MACRO_TERRAIN
#include "height_field.h"
#include "grass_field_heights.glsl"
#endif

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec2 field_uv;
layout(location = 2) flat in ivec4 macro_cells;
layout(location = 0) out vec4 out_color;

void main() {
    ivec2 cell = grass_macro_cell(field_uv, macro_cells.xy, macro_cells.zw);
    GrassCell c = field_cells[cell.y * field.cells.x + cell.x];
    vec2 p = grass_macro_patch_point(field_uv, cell, c.signs.xy);  // the tiled bake frames the cell: uv = p
    // One field unit is one cell, which the tiled bake frames: the patch point moves as field_uv
    // does, turned by the cell's mirror.
    vec2 dx = dFdx(field_uv) * c.signs.xy, dy = dFdy(field_uv) * c.signs.xy;
    vec4 albedo = textureGrad(slice_albedo, vec3(p, 0.0), dx, dy);
#ifdef GRASS_MACRO_TERRAIN
    float ground = grid_height(cell);
#else
    float ground = 0.0;
#endif
    vec4 blades = textureGrad(slice_blades, vec3(p, 0.0), dx, dy);
    vec2 band = grass_macro_blade_band(field, cell, c.signs.xy, ground, blades.zw);
    float alpha = grass_slice_coverage(grass_slice_alpha(albedo, blades, c.densities, band));
    vec3 n = grass_mirror_vector(grass_slice_normal(textureGrad(slice_normal, vec3(p, 0.0), dx, dy).xyz), c.signs.xy);
    out_color = grass_lit_output(albedo.rgb, world_position, n, alpha, field.patch_top.y);
}
