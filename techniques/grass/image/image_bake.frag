#version 450
#extension GL_GOOGLE_include_directive : require
// grass.image, load phase: the patch seen from above (Lemme §4.2, L402: "rendered with an
// orthographic camera from above"), storing what Lemme's slice stores (L390, L406): the blade's
// colour (alpha: covered), its normal (turned up, the side the bake sees), so the slice is lit
// per pixel every frame, and its blade map texel (blade_texels.h: threshold, root).
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "blade_alpha.h"
#include "patch_bake.h"
#include "blade_texels.h"

layout(set = 0, binding = 1, std140) uniform BakeBlock { PatchBake bake; };

layout(location = 0) in vec3 patch_position;
layout(location = 1) in vec3 patch_normal;
layout(location = 2) in vec2 strip_uv;
layout(location = 3) in float colour;
layout(location = 4) flat in float taper;
layout(location = 5) flat in float threshold;
layout(location = 6) flat in vec2 root;
layout(location = 0) out vec4 out_albedo;  // rgb albedo, a covered
layout(location = 1) out vec4 out_normal;  // xyz patch-space normal
layout(location = 2) out vec4 out_blades;  // the blade map

void main() {
    if (!blade_opaque(strip_uv, taper)) discard;
    vec3 n = normalize(patch_normal);
    if (dot(n, bake.toward_viewer.xyz) < 0.0) n = -n;
    out_albedo = vec4(draw.albedo.rgb * colour, 1.0);
    out_normal = vec4(n, 0.0);
    out_blades = vec4(threshold, threshold, root);
}
