// The BTF slices' vertex stage (grass.slices): each cell's 2n vertical quads and its horizontal
// one (Boulanger §4.2.3, Algorithm 3), placed and mirrored with the cell
// (PassContext::draw_over_population). Per vertex, as Algorithm 3 does: which side of its slice
// the eye is on (the front or back view of Figure 4.6), the weights of the five baked light
// directions for the light seen in the patch's own axes (App. A; a mirrored cell sees the light
// mirrored), and the light's irradiance on a surface facing it. Included after the technique's
// parameter block, which has `slices`.
//
// On a terrain every vertex is lifted by the ground under it (grass_terrain.h), as each blade is
// by the ground under its root: a vertical quad comes cut in two (slices_graph.cpp), its cut
// placed here where the cell's ground diagonal crosses it, so each half stands on one ground
// triangle; the horizontal quad is split along that diagonal as grass.image's is. A flat cell
// draws as before.
#include "frame_uniforms.glsl"
#include "scene_lighting.glsl"
#include "btf_interpolation.h"
#include "grass_terrain.h"

layout(location = 0) in vec4 quad_position;             // patch space
layout(location = 1) in vec4 quad_uv;                   // u, v; axis (0 x, 1 z, 2 horizontal); slice
                                                        // (horizontal: the frame's width in x)
layout(location = 2) in mat4 instance_model;             // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8
layout(location = 9) in vec4 corner_densities;           // patch order (grass_density.h)

layout(location = 0) out vec2 uv;
layout(location = 2) out vec4 weights0123;  // btf_light_weights, interpolated and renormalised per fragment
layout(location = 3) out float weight4;
layout(location = 4) out vec3 light_irradiance;  // on a surface facing the light
layout(location = 5) flat out vec4 densities;
layout(location = 6) flat out ivec2 layer;   // x: the albedo layer (-1: the horizontal slice); y: its first lit row
layout(location = 7) flat out mat4 model;    // locations 7-10: where a blade's root is (grass_lod_band.glsl, in the fragment stage)

void main() {
    int axis = int(quad_uv.z), slice = int(quad_uv.w), n = frame.technique.slices;
    vec2 mirror = vec2(sign(instance_model[0][0]), sign(instance_model[2][2]));
    vec3 lifts = vec3(instance_normal_matrix[0].w, instance_normal_matrix[1].w, instance_normal_matrix[2].w);
    vec4 position = vec4(quad_position.xyz, 1.0);
    uv = quad_uv.xy;
    if (quad_position.w == 1.0) {
        // A cut of a vertical quad: its position across holds the frame's start, its u the end.
        int across = axis == 0 ? 2 : 0;
        float start = position[across], end = quad_uv.x;
        float cut = clamp(grass_diagonal_crossing(axis, axis == 0 ? position.x : position.z, mirror), start, end);
        position[across] = cut;
        uv.x = (cut - start) / (end - start);
    } else if (axis == 2 && lifts != vec3(0.0) && mirror.x * mirror.y > 0.0) {
        position.x += (1.0 - 2.0 * uv.x) * quad_uv.w;  // reflected across its frame in x
        uv.x = 1.0 - uv.x;
    }
    vec4 world = instance_model * position + vec4(0.0, grass_terrain_lift(lifts, position.xz, mirror), 0.0, 0.0);
    densities = corner_densities;
    model = instance_model;

    if (axis == 2) {
        layer = ivec2(-1, 0);
    } else {
        vec3 eye = (inverse(instance_model) * vec4(frame.camera_position.xyz, 1.0)).xyz;
        // The quad's four vertices share its plane, so they agree on the side.
        bool front = axis == 0 ? eye.x >= position.x : eye.z >= position.z;
        int l = (axis * n + slice) * 2 + (front ? 0 : 1);
        layer = ivec2(l, l * BTF_LIGHTS);
    }

    int light_type = int(frame.light_position.w);
    vec3 toward_light = light_type == LIGHT_DIRECTIONAL ? -frame.light_axis.xyz
                                                        : normalize(frame.light_position.xyz - world.xyz);
    light_irradiance = scene_light_irradiance(world.xyz, toward_light);
    // transpose(normal matrix) = inverse(model) for directions: the light in patch space.
    mat3 normal_matrix = mat3(instance_normal_matrix[0].xyz, instance_normal_matrix[1].xyz, instance_normal_matrix[2].xyz);
    BtfWeights w = btf_light_weights(transpose(normal_matrix) * toward_light);
    weights0123 = w.w0123;
    weight4 = w.w4;
    gl_Position = frame.view_proj * world;
}
