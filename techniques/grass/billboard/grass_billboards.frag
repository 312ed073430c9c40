#version 450
#extension GL_GOOGLE_include_directive : require
// grass.billboard: the baked radiance where the baked blade's threshold is within the cell's
// density there (a texel with no blade holds PATCH_BAKE_EMPTY, which no density reaches).
#include "grass_billboard_params.h"
#include "frame_uniforms.glsl"
#include "patch_bake.h"
#include "grass_density.h"

layout(set = 0, binding = 1) uniform sampler2DArray billboard;  // NEAREST: thresholds are not blended

layout(location = 0) in vec2 uv;
layout(location = 1) flat in float layer;
layout(location = 2) flat in vec4 densities;
layout(location = 3) in vec2 ground_xz;
layout(location = 0) out vec4 out_color;

void main() {
    vec4 texel = texture(billboard, vec3(uv, layer));
    if (!grass_blade_drawn(texel.a, grass_root_density(densities, ground_xz))) discard;
    out_color = vec4(texel.rgb, 1.0);
}
