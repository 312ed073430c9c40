#version 450
#extension GL_GOOGLE_include_directive : require
// Any grass technique's load-phase bake: the patch's blades (the population's prototype, one
// copy drawn without its cell's placement; tiled, with its 8 neighbours) seen by an orthographic
// bake camera (patch_bake.h).
#include "frame_uniforms.glsl"
#include "patch_bake.h"

layout(set = 0, binding = 1, std140) uniform BakeBlock { PatchBake bake; };

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 10) in vec4 blade_strip;  // u, v, threshold, colour
layout(location = 11) in vec4 blade_root;   // root x, root z, taper, 0

layout(location = 0) out vec3 patch_position;
layout(location = 1) out vec3 patch_normal;
layout(location = 2) out vec2 strip_uv;
layout(location = 3) out float colour;
layout(location = 4) flat out float taper;
layout(location = 5) flat out float threshold;
layout(location = 6) flat out vec2 root;  // the blade's root, patch x and z (the tile's copy's)

void main() {
    vec3 tile = bake.tiles.x > 0.0 ? patch_bake_tile(gl_InstanceIndex) : vec3(0.0);
    patch_position = in_position + tile;
    root = blade_root.xy + tile.xz;
    patch_normal = in_normal;
    strip_uv = blade_strip.xy;
    colour = blade_strip.w;
    taper = blade_root.z;
    threshold = blade_strip.z;
    gl_Position = bake.view_proj * vec4(patch_position, 1.0);
}
