#version 450
#extension GL_GOOGLE_include_directive : require
// grass.billboard: the baked images on quads, once per cell (PassContext::draw_over_population).
// Crossed: the two quads in the patch's xy and zy planes, placed (and mirrored) with the cell.
// Camera-facing: the xy quad turned about the cell's vertical axis towards the camera.
// On a terrain each vertex is lifted by the ground under its foot, as a blade is by the ground
// under its root (grass_terrain.h): the quads are cut at the cell's centre, where the ground's
// diagonal crosses them, so each half's foot lies on one of the ground's triangles. Beyond the
// cell (the bake frame is wider than the patch) the ground's plane is extended.
#include "grass_billboard_params.h"
#include "frame_uniforms.glsl"
#include "grass_terrain.h"

layout(location = 0) in vec4 quad_position;  // patch space; w = image layer
layout(location = 1) in vec4 quad_uv;
layout(location = 2) in mat4 instance_model;             // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8: w, the terrain's corner heights
layout(location = 9) in vec4 corner_densities;           // patch order (grass_density.h)

layout(location = 0) out vec2 uv;
layout(location = 1) flat out float layer;
layout(location = 2) flat out vec4 densities;

void main() {
    uv = quad_uv.xy;
    layer = quad_position.w;
    densities = corner_densities;
    vec3 p = quad_position.xyz;
    vec4 world;
    vec2 foot = p.xz;  // patch space
    if (frame.technique.orientation == GRASS_BILLBOARD_CAMERA_FACING) {
        vec3 centre = (instance_model * vec4(0.5, 0.0, 0.5, 1.0)).xyz;
        float scale = length(instance_model[1].xyz);
        vec3 to_camera = frame.camera_position.xyz - centre;
        vec3 right = vec3(to_camera.z, 0.0, -to_camera.x);
        float length_right = length(right);
        right = length_right > 1e-6 ? right / length_right : vec3(1.0, 0.0, 0.0);
        world = vec4(centre + right * ((p.x - 0.5) * scale) + vec3(0.0, p.y * scale, 0.0), 1.0);
        foot = (inverse(instance_model) * vec4(world.x, centre.y, world.z, 1.0)).xz;
    } else {
        world = instance_model * vec4(p, 1.0);
    }
    vec3 lifts = vec3(instance_normal_matrix[0].w, instance_normal_matrix[1].w, instance_normal_matrix[2].w);
    vec2 mirror = vec2(sign(instance_model[0][0]), sign(instance_model[2][2]));
    world.y += grass_terrain_lift(lifts, foot, mirror);
    gl_Position = frame.view_proj * world;
}
