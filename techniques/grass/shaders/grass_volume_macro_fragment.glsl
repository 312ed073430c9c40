// The volume's fragment stage over macro-cells (grass.volume with macro_cells, and grass.lod's
// middle band under culling = "quadtree"; Lemme §6.2, eq 6.6): the ray walks the n k slice planes
// of the macro-cell in each direction (volume_walk.h with n k planes), and each plane it meets
// shows its own cell's copy of the tiled slices: the slice that cell's mirror puts there
// (grass_macro_slice), read at the mirrored point filtered over the hit's footprint, thinned by
// that cell's densities and, in grass.lod, by that cell's band (grass_lod_band.glsl,
// grass_slice_coverage.glsl), lit with the mirrored baked normal; composited front to back as for
// one cell (grass_volume_fragment.glsl). The depth written is that of the blade where the gathered opacity passes a_r.
// Included after the technique's parameter block, which has `slices`.
//
// With GRASS_MACRO_TERRAIN (grass_volume_macro_vertex.glsl), each hit's lookup is shifted down by
// the ground under it, read from the field's grid heights on its own cell's two triangles, as one
// cell's is from its corners (grass_volume_fragment.glsl, eq 6.16-6.18); a hit below the ground
// or above the patch over it sees nothing. The cell's band is taken at its centre lifted to its
// first corner's ground, where a copy's model puts it (grass_lod_band.glsl).
#include "frame_uniforms.glsl"
#include "grass_density.h"
#include "grass_macro_cells.h"
#include "grass_shading.glsl"
#include "grass_slice_coverage.glsl"
#include "volume_gather.glsl"
#include "grass_lod_band.glsl"
#include "volume_walk.h"
#ifndef GRASS_VOLUME_SLICES
#define GRASS_VOLUME_SLICES (frame.technique.slices)
#endif

layout(set = 0, binding = 1) uniform sampler2DArray slice_albedo;  // trilinear, or NEAREST (mip_filter = "none")
layout(set = 0, binding = 2) uniform sampler2DArray slice_normal;  // the same
layout(set = 0, binding = 8) uniform sampler2DArray slice_blades;  // the same (blade_texels.h)
layout(set = 0, binding = 3, std140) uniform FieldBlock { GrassMacroField field; };
layout(set = 0, binding = 4, std430) readonly buffer CellBlock { GrassCell field_cells[]; };
#ifdef GRASS_MACRO_TERRAIN
#include "height_field.h"
#include "grass_field_heights.glsl"
#endif

// GRASS_VOLUME_PER_SAMPLE: the exit point interpolated at each covered sample, so under MSAA the
// walk runs once per sample (grass.lod's middle_per_sample) and the slices' texels are anti-aliased.
#ifdef GRASS_VOLUME_PER_SAMPLE
layout(location = 0) sample in vec3 exit_q;
#else
layout(location = 0) in vec3 exit_q;
#endif
layout(location = 1) flat in vec3 eye_q;
layout(location = 2) flat in ivec4 macro_cells;
#ifdef GRASS_MACRO_TERRAIN
layout(location = 3) flat in vec2 heights;  // the cuboid's bottom and height (grass_volume_macro_vertex.glsl)
#endif
layout(location = 0) out vec4 out_color;

void main() {
    int n = GRASS_VOLUME_SLICES;
    ivec2 first = macro_cells.xy, span = macro_cells.zw;
    vec2 planes = vec2(n) * vec2(span);
    float size = field.origin_size.w;
    vec3 origin = field.origin_size.xyz + vec3(first.x, 0.0, first.y) * size;
    vec3 extent = vec3(span.x, field.patch_top.x, span.y) * size;
#ifdef GRASS_MACRO_TERRAIN
    origin.y += heights.x;
    extent.y = heights.y;
#endif
    vec3 to_exit = exit_q - eye_q;
    vec3 e = eye_q + volume_entry(eye_q, to_exit) * to_exit;  // eq 5.4
    vec3 d = exit_q - e;
    VolumeWalk walk = volume_walk(e, d, planes);
    VolumeGather gathered = volume_gather_start();
    ivec2 crossed = ivec2(0);
    int steps = int(planes.x + planes.y) + 1;
    for (int i = 0; i < steps; ++i) {
        VolumeHit hit = volume_next_hit(walk, e, crossed, planes);
        if (hit.lambda > 1.0) break;
        crossed += hit.axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        vec3 q = e + hit.lambda * d;
        vec2 u = vec2(first) + q.xz * vec2(span);  // field coordinates
        // Plane j of the macro-cell is plane j % n of its cell; the planes lie inside cells
        // ((k + 0.5) / n), so the cell u is in is the plane's.
        int plane = clamp(hit.slice, 0, (hit.axis == 0 ? span.x : span.y) * n - 1);
        ivec2 cell = grass_macro_cell(u, first, span);
        GrassCell c = field_cells[cell.y * field.cells.x + cell.x];
        float texel_height = q.y;
#ifdef GRASS_MACRO_TERRAIN
        texel_height = (heights.x + q.y * heights.y - grid_ground(cell, u)) / (field.patch_top.x * size);
        if (texel_height < 0.0 || texel_height > 1.0) continue;
        float ground = grid_height(cell);
#else
        float ground = 0.0;
#endif
        vec2 s = c.signs.xy;
        int slice = grass_macro_slice(plane % n, n, hit.axis == 0 ? s.x : s.y);
        vec2 p = grass_macro_patch_point(u, cell, s);
        if (hit.axis == 0) p.x = (float(slice) + 0.5) / float(n); else p.y = (float(slice) + 0.5) / float(n);
        // Slices along x are baked looking along x (u = z), those along z looking along z (u = x).
        vec3 texel = hit.axis == 0 ? vec3(p.y, 1.0 - texel_height, float(slice))
                                   : vec3(p.x, 1.0 - texel_height, float(n + slice));
        // The footprint (world): the tiled bake's u spans one cell, v the patch's height (the
        // ground's slope aside).
        vec3 world = origin + q * extent;
        vec4 g = volume_slice_footprint(normalize(world - frame.camera_position.xyz), hit.axis,
                                        -(frame.view * vec4(world, 1.0)).z / frame.viewport.z,
                                        vec2(size, field.patch_top.x * size));
        vec2 gx = g.xy, gy = g.zw;
        vec4 albedo = textureGrad(slice_albedo, texel, gx, gy);
        vec4 blades = textureGrad(slice_blades, texel, gx, gy);
        vec2 band = grass_macro_blade_band(field, cell, s, ground, blades.zw);
        float hit_alpha = grass_slice_alpha(albedo, blades, c.densities, band);
        if (!(hit_alpha > 0.0)) continue;
        vec3 normal = grass_mirror_vector(grass_slice_normal(textureGrad(slice_normal, texel, gx, gy).xyz), s);
        vec3 radiance = grass_lit_output(albedo.rgb, world, normal, 1.0, field.patch_top.y).rgb;
        if (volume_gather_add(gathered, radiance, hit_alpha, world)) break;
    }
    out_color = volume_gather_output(gathered);
}
