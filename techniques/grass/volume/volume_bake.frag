#version 450
#extension GL_GOOGLE_include_directive : require
// grass.volume, load phase: one vertical slice (Lemme §4.2.1, Figure 4.7): the blades of the
// patch between the slice's two clipping planes, seen by an orthographic camera along the
// slice's axis, storing what the slice stores (L390, L406): the blade's colour (alpha: covered),
// its normal turned to the side the bake sees, and its blade map texel (blade_texels.h:
// threshold, root). The clipping planes cut per fragment, so a
// blade crossing them is split exactly at the planes.
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
    if (!patch_bake_keeps(bake, patch_position) || !blade_opaque(strip_uv, taper)) discard;
    vec3 n = normalize(patch_normal);
    if (dot(n, bake.toward_viewer.xyz) < 0.0) n = -n;
    out_albedo = vec4(draw.albedo.rgb * colour, 1.0);
    out_normal = vec4(n, 0.0);
    out_blades = vec4(threshold, threshold, root);
}
