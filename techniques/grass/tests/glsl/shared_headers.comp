#version 450
// Compiles the grass family's GLSL/C++ headers as GLSL (ctest grass:glsl_headers), so a C++-only
// construct in them fails here and not in a technique's shader later.
#extension GL_GOOGLE_include_directive : require
#include "blade_alpha.h"
#include "blade_curve.h"
#include "blade_texels.h"
#include "cell_mirroring.h"
#include "grass_density.h"
#include "lod_selection.h"
#include "mip_filters.h"
#include "patch_bake.h"
#include "volume_walk.h"

layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { vec4 values[]; };

void main() {
    vec3 b = vec3(0.1, 1.0, 0.0), g = vec3(0.0, -0.4, 0.0);
    values[0] = vec4(blade_point(b, g, 0.5), blade_max_pull(b.y));
    values[1] = vec4(blade_tangent(b, g, 0.5), grass_fract(-0.25));
    vec2 s = grass_mirror_signs(ivec2(-3, 7), 1u);
    values[2] = vec4(grass_mirror_patch_point(vec3(0.2, 0.0, 0.7), s), float(grass_hash(5u)));
    values[3] = vec4(grass_mirror_slice_uv(vec2(3.25, -1.5), s), s);
    vec2 uv = vec2(0.3, 0.6);
    values[5] = grass_patch_corner_densities(vec4(0.1, 0.2, 0.3, 0.4), s);
    values[6] = vec4(grass_root_density(values[5], vec2(0.25, 0.75)), grass_blade_drawn(0.5, 0.4) ? 1.0 : 0.0, 0.0, 0.0);
    values[7] = vec4(lod_far_opacity(0.3, 0.8, 0.5), lod_near_opacity(0.3, 0.8, 0.5), lod_window(0.25),
                     lod_weight_vertical_slices(30.0, 10.0, 20.0, 40.0, 80.0) + lod_weight_horizontal_slice(15.0, 10.0, 20.0));
    values[8] = vec4(lod_in_first(0.2, 0.5, 0.5) ? 1.0 : 0.0, lod_in_second(0.3, 0.5, 0.5) ? 1.0 : 0.0,
                     lod_first_opacity_smooth(0.2, 0.5, 0.5, 0.02), lod_second_opacity_smooth(0.2, 0.0, 0.5, 0.02));
    vec2 band = lod_band(GRASS_LOD_VOLUME, lod_cuts(12.0, 4.0, 8.0, 10.0, 20.0));
    values[11] = vec4(band, grass_blade_in_band(0.5, 0.8, band) ? 1.0 : 0.0, lod_ramp_down(5.0, 5.0, 5.0));
    values[12] = vec4(lod_beyond(0.4, 0.5, GRASS_LOD_WINDOW_SMOOTHSTEP, 0.05),
                      lod_beyond_mean(0.3, 0.6, 0.5, GRASS_LOD_WINDOW_LINEAR, 0.05),
                      lod_band_interval(0.3, 0.8, band, GRASS_LOD_WINDOW_LINEAR, 0.05));
    values[13] = vec4(blade_texel_interval(vec2(0.2, 0.6), 0.7, band, GRASS_LOD_WINDOW_SMOOTHSTEP, 0.05),
                      lod_screen_door(vec2(3.5, 7.5)), lod_interval_draws(vec2(0.0, 0.5), 0.25) ? 1.0 : 0.0);
    VolumeWalk walk = volume_walk(vec3(0.1, 1.0, 0.3), vec3(0.5, -0.8, 0.0), 4.0);
    VolumeHit hit = volume_next_hit(walk, vec3(0.1, 1.0, 0.3), ivec2(1, 0), 4.0);
    values[9] = vec4(hit.lambda, float(hit.axis + hit.slice), volume_entry(vec3(-0.5, 0.5, 0.5), vec3(1.0, 0.0, 0.0)),
                     walk.first.x);
    PatchBake bake;
    bake.toward_viewer = vec4(1.0, 0.0, 0.0, 0.0);
    bake.section = vec4(0.0, 0.5, 0.0, 0.0);
    values[10] = vec4(patch_bake_keeps(bake, vec3(0.25, 0.0, 0.0)) ? 1.0 : 0.0, 0.0, 0.0, 0.0);
    values[4] = vec4(blade_half_width(uv.y, 2.0), blade_opaque(uv, 2.0) ? 1.0 : 0.0, blade_alpha(uv, 2.0, 0.01),
                     blade_coverage(2.0));
}
