// grass.slices, load phase: one side of one slice (Boulanger §4.2.3, Figure 4.5): the blades of
// the patch (and its 8 neighbours) between the slice's two clipping planes, seen by an
// orthographic camera along the slice's axis, storing Figure 4.6's data for that view: the
// blade's albedo (the ambient row; alpha: covered), its colour under each of the five baked light
// directions (btf_interpolation.h), shaded on the side the bake sees, and its blade map texel
// (blade_texels.h: the density threshold of Figure 4.9's texture, and the blade's root). The population's transmission gamma (eq 4.1) is baked into the rows.
// Each row's alpha is the light's visibility there: 1 without SLICES_BAKE_SHADOWS (the family's
// local shading); with it, the blades' shadows looked up in the light's depth layer
// (bake_shadows.h), every blade casting; the frame pass thins them by the cell's density (eq 4.7).
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "blade_alpha.h"
#include "btf_interpolation.h"
#include "patch_bake.h"
#include "blade_texels.h"

layout(set = 0, binding = 1, std140) uniform BakeBlock { PatchBake bake; };
#ifdef SLICES_BAKE_SHADOWS
#include "bake_shadows.h"
layout(set = 0, binding = 2) uniform sampler2DArrayShadow light_depth;  // compare, LINEAR: 2 x 2 PCF
layout(set = 0, binding = 3, std140) uniform ShadowBlock { BakeShadows shadows; };
#endif

layout(location = 0) in vec3 patch_position;
layout(location = 1) in vec3 patch_normal;
layout(location = 2) in vec2 strip_uv;
layout(location = 3) in float colour;
layout(location = 4) flat in float taper;
layout(location = 5) flat in float threshold;
layout(location = 6) flat in vec2 root;
layout(location = 0) out vec4 out_albedo;  // rgb albedo, a covered
layout(location = 1) out vec4 out_row0;    // Y+
layout(location = 2) out vec4 out_row1;    // X+
layout(location = 3) out vec4 out_row2;    // Z+
layout(location = 4) out vec4 out_row3;    // X-
layout(location = 5) out vec4 out_row4;    // Z-
layout(location = 6) out vec4 out_blades;  // the blade map

float light_visibility(int row, vec3 n) {
#ifdef SLICES_BAKE_SHADOWS
    vec3 p = bake_shadow_point(patch_position, n, btf_light_direction(row), shadows.offsets.x);
    vec3 at = bake_shadow_coord(shadows.lookup[row], p);
    return texture(light_depth, vec4(at.xy, float(row), at.z));
#else
    return 1.0;
#endif
}

void main() {
    if (!patch_bake_keeps(bake, patch_position) || !blade_opaque(strip_uv, taper)) discard;
    vec3 n = normalize(patch_normal);
    if (dot(n, bake.toward_viewer.xyz) < 0.0) n = -n;
    vec3 albedo = draw.albedo.rgb * colour;
    float gamma = draw.albedo.w;
    out_albedo = vec4(albedo, 1.0);
    out_blades = vec4(threshold, threshold, root);
    out_row0 = vec4(btf_baked_row(albedo, n, 0, gamma), light_visibility(0, n));
    out_row1 = vec4(btf_baked_row(albedo, n, 1, gamma), light_visibility(1, n));
    out_row2 = vec4(btf_baked_row(albedo, n, 2, gamma), light_visibility(2, n));
    out_row3 = vec4(btf_baked_row(albedo, n, 3, gamma), light_visibility(3, n));
    out_row4 = vec4(btf_baked_row(albedo, n, 4, gamma), light_visibility(4, n));
}
