// The image's fragment stage (grass.image, and grass.lod's far band): the baked top view, filtered
// (mip_passes.hpp), where its blades' thresholds are within the cell's density at their root
// (Lemme L611: "fragments of hidden grass blades are discarded because of their density
// threshold") and, in grass.lod, within the image's band (grass_lod_band.glsl), made coverage by
// grass_slice_coverage.glsl; lit per pixel with the baked normal by the family's one model.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "grass_density.h"
#include "grass_shading.glsl"
#include "grass_slice_coverage.glsl"
#include "grass_lod_band.glsl"

layout(set = 0, binding = 1) uniform sampler2DArray slice_albedo;  // trilinear, or NEAREST (mip_filter = "none")
layout(set = 0, binding = 2) uniform sampler2DArray slice_normal;  // the same
layout(set = 0, binding = 8) uniform sampler2DArray slice_blades;  // the same (blade_texels.h)

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec2 uv;
layout(location = 3) flat in vec4 densities;
layout(location = 4) flat in vec3 normal_matrix[3];
layout(location = 7) flat in mat4 model;  // locations 7-10: where a blade's root is (grass_lod_band.glsl)
layout(location = 0) out vec4 out_color;

void main() {
    vec4 albedo = texture(slice_albedo, vec3(uv, 0.0));
    vec4 blades = texture(slice_blades, vec3(uv, 0.0));
    float alpha = grass_slice_coverage(grass_slice_alpha(albedo, blades, densities, grass_blade_band(model, blades.zw)));
    vec3 n = mat3(normal_matrix[0], normal_matrix[1], normal_matrix[2]) * grass_slice_normal(texture(slice_normal, vec3(uv, 0.0)).xyz);
    out_color = grass_lit_output(albedo.rgb, world_position, n, alpha, draw.albedo.w);
}
