// The image's fragment stage (grass.image, and grass.lod's far band): the baked top view where its
// blade's threshold is within the cell's density at that point (Lemme L611: "fragments of hidden
// grass blades are discarded because of their density threshold") and, in grass.lod, within the
// image's band (grass_lod_band.glsl); lit per pixel with the baked normal by the family's one
// model.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "grass_density.h"
#include "grass_shading.glsl"

layout(set = 0, binding = 1) uniform sampler2D slice_albedo;  // NEAREST: thresholds are not blended
layout(set = 0, binding = 2) uniform sampler2D slice_normal;  // NEAREST

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec2 patch_xz;
layout(location = 3) flat in vec4 densities;
layout(location = 4) flat in vec3 normal_matrix[3];
layout(location = 7) flat in vec2 band;  // grass_lod_band.glsl
layout(location = 0) out vec4 out_color;

void main() {
    vec4 albedo = texture(slice_albedo, uv);
    if (!grass_blade_in_band(albedo.a, grass_root_density(densities, patch_xz), band)) discard;
    vec3 n = mat3(normal_matrix[0], normal_matrix[1], normal_matrix[2]) * texture(slice_normal, uv).xyz;
    out_color = grass_lit_output(albedo.rgb, world_position, n, 1.0, draw.albedo.w);
}
