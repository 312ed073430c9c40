#version 450
#extension GL_GOOGLE_include_directive : require
// grass.billboard, load phase: the patch's blades (the population's prototype, one copy drawn
// without its cell's placement) seen by the layer's orthographic bake camera.
#include "grass_billboard_params.h"
#include "frame_uniforms.glsl"
#include "billboard_bake.h"

layout(set = 0, binding = 1, std140) uniform BakeBlock { BillboardBake bake; };

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

void main() {
    patch_position = in_position;
    patch_normal = in_normal;
    strip_uv = blade_strip.xy;
    colour = blade_strip.w;
    taper = blade_root.z;
    threshold = blade_strip.z;
    gl_Position = bake.view_proj * vec4(in_position, 1.0);
}
