// The volume's fragment stage (grass.volume, and grass.lod's middle band): Lemme's ray cast
// through the cell's vertical slices (§5.2, eq 5.3-5.21). The ray from the eye to this exit point
// enters the cuboid (volume_entry), walks the slice planes in order (volume_walk.h), and at each
// samples the slice's baked texel, filtered over the hit's footprint (volume_slice_footprint): its
// alpha the share its blades cover that the density at their root and the representation's band
// (grass_lod_band.glsl) keep (grass_slice_coverage.glsl), lit per pixel with the baked normal by
// the family's one model and composited front to back (eq 5.19-5.20). The depth written is that
// of the blade where the gathered opacity passes a_r (Lemme: the first blade's, "used for
// modifying the depth value"; a filtered texel's faint edge is not a blade), so overlapping cuboids and
// the ground resolve by the depth test. What the ray gathers is made coverage as a slice's alpha
// is (alpha-to-coverage, or the alpha test at a_r). Included after the technique's parameter
// block, which has `slices`.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "grass_density.h"
#include "grass_shading.glsl"
#include "grass_slice_coverage.glsl"
#include "volume_gather.glsl"
#include "volume_walk.h"
#include "grass_terrain.h"
#include "grass_lod_band.glsl"  // a blade's band; in grass.lod's volume levels, the level's uniform and slices
#ifndef GRASS_VOLUME_SLICES
#define GRASS_VOLUME_SLICES (frame.technique.slices)
#endif

layout(set = 0, binding = 1) uniform sampler2DArray slice_albedo;  // trilinear, or NEAREST (mip_filter = "none")
layout(set = 0, binding = 2) uniform sampler2DArray slice_normal;  // the same
layout(set = 0, binding = 8) uniform sampler2DArray slice_blades;  // the same (blade_texels.h)
layout(set = 0, binding = 3, std140) uniform BoxBlock { VolumeBox box; };

// GRASS_VOLUME_PER_SAMPLE: the exit point interpolated at each covered sample, so under MSAA the
// walk runs once per sample (grass.lod's middle_per_sample) and the slices' texels are anti-aliased.
#ifdef GRASS_VOLUME_PER_SAMPLE
layout(location = 0) sample in vec3 exit_q;
#else
layout(location = 0) in vec3 exit_q;
#endif
layout(location = 1) flat in vec3 eye_q;
layout(location = 2) flat in vec4 densities;
layout(location = 3) flat in mat4 model;
layout(location = 7) flat in vec3 normal_matrix[3];
layout(location = 11) flat in vec3 lifts;   // grass_terrain.h
layout(location = 12) flat in vec2 stretch; // the cuboid's bottom and top moved by (grass_volume_vertex.glsl)
layout(location = 0) out vec4 out_color;

void main() {
    int n = GRASS_VOLUME_SLICES;
    vec3 to_exit = exit_q - eye_q;
    vec3 e = eye_q + volume_entry(eye_q, to_exit) * to_exit;  // eq 5.4: the ray's entry
    vec3 d = exit_q - e;
    VolumeWalk walk = volume_walk(e, d, float(n));
    VolumeGather gathered = volume_gather_start();
    ivec2 crossed = ivec2(0);
    // The (possibly stretched) cuboid q spans, and the mirror that puts a patch point in world order.
    vec3 origin = box.origin.xyz + vec3(0.0, stretch.x, 0.0);
    vec3 extent = box.extent.xyz + vec3(0.0, stretch.y - stretch.x, 0.0);
    vec2 mirror = vec2(sign(model[0][0]), sign(model[2][2]));
    for (int i = 0; i < 2 * n + 1; ++i) {
        VolumeHit hit = volume_next_hit(walk, e, crossed, float(n));
        if (hit.lambda > 1.0) break;  // the ray leaves the cuboid first
        crossed += hit.axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        vec3 q = e + hit.lambda * d;  // eq 5.18
        int slice = clamp(hit.slice, 0, n - 1);
        vec3 p = origin + q * extent;
        // On a terrain the lookup is shifted down by the ground under the hit (eq 6.16-6.18), and a
        // hit below the ground or above the patch over it sees nothing. A flat cell reads exactly
        // q.y, as without a terrain (the texel's clamped edge included).
        float lift = grass_terrain_lift(lifts, p.xz, mirror) / model[1][1];
        float height = q.y * (extent.y / box.extent.y) + (stretch.x - lift) / box.extent.y;
        if (stretch != vec2(0.0) && (height < 0.0 || height > 1.0)) continue;
        // Slices along x are baked looking along x (u = z), those along z looking along z (u = x).
        vec3 texel = hit.axis == 0 ? vec3(q.z, 1.0 - height, float(slice)) : vec3(q.x, 1.0 - height, float(n + slice));
        // The footprint (world): u spans the box across the plane, v the patch's height.
        vec3 world = (model * vec4(p, 1.0)).xyz;
        vec4 g = volume_slice_footprint(normalize(world - frame.camera_position.xyz), hit.axis,
                                        -(frame.view * vec4(world, 1.0)).z / frame.viewport.z,
                                        vec2((hit.axis == 0 ? box.extent.z * abs(model[2][2]) : box.extent.x * abs(model[0][0])),
                                             box.extent.y * model[1][1]));
        vec2 gx = g.xy, gy = g.zw;
        vec4 albedo = textureGrad(slice_albedo, texel, gx, gy);
        vec4 blades = textureGrad(slice_blades, texel, gx, gy);
        float hit_alpha = grass_slice_alpha(albedo, blades, densities, grass_blade_band(model, blades.zw));
        if (!(hit_alpha > 0.0)) continue;
        vec3 normal = mat3(normal_matrix[0], normal_matrix[1], normal_matrix[2]) *
                      grass_slice_normal(textureGrad(slice_normal, texel, gx, gy).xyz);
        vec3 radiance = grass_lit_output(albedo.rgb, world, normal, 1.0, draw.albedo.w).rgb;
        if (volume_gather_add(gathered, radiance, hit_alpha, world)) break;
    }
    out_color = volume_gather_output(gathered);
}
