// The image's vertex stage (grass.image, and grass.lod's far band): one horizontal quad per cell a
// little above the ground (Lemme §5.3, L611), placed and mirrored with the cell
// (PassContext::draw_over_population). Included after the technique's parameter block.
#include "frame_uniforms.glsl"
#include "grass_lod_band.glsl"

layout(location = 0) in vec4 quad_position;             // patch space
layout(location = 1) in vec4 quad_uv;
layout(location = 2) in mat4 instance_model;             // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8
layout(location = 9) in vec4 corner_densities;           // patch order (grass_density.h)

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec2 uv;
layout(location = 2) out vec2 patch_xz;
layout(location = 3) flat out vec4 densities;
layout(location = 4) flat out vec3 normal_matrix[3];  // locations 4-6
layout(location = 7) flat out vec2 band;              // grass_lod_band.glsl

void main() {
    vec4 world = instance_model * vec4(quad_position.xyz, 1.0);
    world_position = world.xyz;
    uv = quad_uv.xy;
    patch_xz = quad_position.xz;
    densities = corner_densities;
    band = grass_representation_band(instance_model);
    for (int c = 0; c < 3; ++c) normal_matrix[c] = instance_normal_matrix[c].xyz;
    gl_Position = frame.view_proj * world;
}
