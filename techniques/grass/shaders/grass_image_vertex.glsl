// The image's vertex stage (grass.image, and grass.lod's far band): one horizontal quad per cell a
// little above the ground (Lemme §5.3, L611), placed and mirrored with the cell
// (PassContext::draw_over_population). Included after the technique's parameter block.
#include "frame_uniforms.glsl"
#include "grass_terrain.h"

layout(location = 0) in vec4 quad_position;             // patch space
layout(location = 1) in vec4 quad_uv;                   // u, v; the frame's width in x and z
layout(location = 2) in mat4 instance_model;             // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8
layout(location = 9) in vec4 corner_densities;           // patch order (grass_density.h)

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec2 uv;
layout(location = 3) flat out vec4 densities;
layout(location = 4) flat out vec3 normal_matrix[3];  // locations 4-6
layout(location = 7) flat out mat4 model;             // locations 7-10: where a blade's root is (grass_lod_band.glsl, in the fragment stage)

void main() {
    // On a terrain (Lemme L902) the quad's corners are lifted onto the ground under them, and its
    // two triangles are split along the ground's own diagonal (height_field.h: (1, 0)-(0, 1) in
    // world order), so the quad runs parallel to the ground's triangles. The buffer's quad splits
    // along (0, 0)-(1, 1) in patch space, which is the ground's where exactly one axis mirrors;
    // elsewhere the quad is reflected across its frame in x. A flat cell draws as before.
    vec2 mirror = vec2(sign(instance_model[0][0]), sign(instance_model[2][2]));
    vec3 lifts = vec3(instance_normal_matrix[0].w, instance_normal_matrix[1].w, instance_normal_matrix[2].w);
    vec4 position = quad_position;
    vec2 corner = quad_uv.xy;
    if (lifts != vec3(0.0) && mirror.x * mirror.y > 0.0) {
        position.x += (1.0 - 2.0 * corner.x) * quad_uv.z;
        corner.x = 1.0 - corner.x;
    }
    vec4 world = instance_model * vec4(position.xyz, 1.0) +
                 vec4(0.0, grass_terrain_lift(lifts, position.xz, mirror), 0.0, 0.0);
    world_position = world.xyz;
    uv = corner;
    densities = corner_densities;
    model = instance_model;
    for (int c = 0; c < 3; ++c) normal_matrix[c] = instance_normal_matrix[c].xyz;
    gl_Position = frame.view_proj * world;
}
