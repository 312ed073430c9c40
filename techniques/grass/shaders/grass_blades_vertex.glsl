// The blades' vertex stage (grass.geometry, and grass.lod's near band): every cell's copy of the
// blade patch in one instanced draw (PassContext::draw_population). A blade whose threshold its
// cell's density does not reach, or that falls outside the representation's band
// (grass_lod_band.glsl), is moved outside the clip volume, all its vertices alike, so it draws
// nothing (Lemme eq 5.22); one inside a transition window draws the screen-door pixels of its
// share (lod_band_interval; all of them alone). Outputs are interpolated at the centroid: with MSAA, a blade thinner
// than a pixel would otherwise extrapolate them to the pixel centre, far outside the strip
// (negative colours). Included after the technique's parameter block.
#include "frame_uniforms.glsl"
#include "grass_density.h"
#include "grass_lod_band.glsl"
#include "grass_terrain.h"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in mat4 instance_model;             // locations 2-5
layout(location = 6) in vec4 instance_normal_matrix[3];  // locations 6-8
layout(location = 9) in vec4 corner_densities;           // patch order (grass_density.h)
layout(location = 10) in vec4 blade_strip;               // u, v, threshold, colour
layout(location = 11) in vec4 blade_root;                // root x, root z, taper, 0

layout(location = 0) centroid out vec3 world_position;
layout(location = 1) centroid out vec3 world_normal;
layout(location = 2) centroid out vec2 strip_uv;
layout(location = 3) centroid out float colour;
layout(location = 4) flat out float taper;
layout(location = 5) flat out vec2 transition;  // the screen-door values drawing it (lod_band_interval)

void main() {
    float density = grass_root_density(corner_densities, blade_root.xy);
    // On a terrain, the blade stands on the ground under its root (Lemme eq 6.13, grass_terrain.h).
    vec2 mirror = vec2(sign(instance_model[0][0]), sign(instance_model[2][2]));
    vec3 lifts = vec3(instance_normal_matrix[0].w, instance_normal_matrix[1].w, instance_normal_matrix[2].w);
    vec4 world = instance_model * vec4(in_position, 1.0) + vec4(0.0, grass_terrain_lift(lifts, blade_root.xy, mirror), 0.0, 0.0);
    world_position = world.xyz;
    world_normal = mat3(instance_normal_matrix[0].xyz, instance_normal_matrix[1].xyz, instance_normal_matrix[2].xyz) *
                   in_normal;
    strip_uv = blade_strip.xy;
    colour = blade_strip.w;
    taper = blade_root.z;
#ifdef GRASS_LOD_REPRESENTATION
    transition = lod_band_interval(blade_strip.z, density, grass_blade_band(instance_model, blade_root.xy),
                                   grass_transition_window(), grass_transition_width());
    bool drawn = transition.y > transition.x;
#else
    transition = vec2(0.0, 1.0);
    bool drawn = grass_blade_drawn(blade_strip.z, density);
#endif
    gl_Position = drawn ? frame.view_proj * world : vec4(2.0, 2.0, 2.0, 1.0);
}
