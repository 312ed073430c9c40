#version 450
#extension GL_GOOGLE_include_directive : require
// grass.billboard, load phase: the blade's outline cut hard, its radiance under the scene's sun
// by the family's model (the side the bake camera sees; alpha: covered), and its blade map texel
// (blade_texels.h: threshold, root).
#include "grass_billboard_params.h"
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "blade_alpha.h"
#include "patch_bake.h"
#include "blade_texels.h"
#include "scene_lighting.glsl"

layout(set = 0, binding = 1, std140) uniform BakeBlock { PatchBake bake; };

layout(location = 0) in vec3 patch_position;
layout(location = 1) in vec3 patch_normal;
layout(location = 2) in vec2 strip_uv;
layout(location = 3) in float colour;
layout(location = 4) flat in float taper;
layout(location = 5) flat in float threshold;
layout(location = 6) flat in vec2 root;
layout(location = 0) out vec4 out_texel;
layout(location = 1) out vec4 out_blades;

void main() {
    if (!blade_opaque(strip_uv, taper)) discard;
    vec3 n = normalize(patch_normal);
    if (dot(n, bake.toward_viewer.xyz) < 0.0) n = -n;
    vec3 irradiance = scene_light_irradiance(patch_position, n);
    if (draw.albedo.w > 0.0) irradiance += draw.albedo.w * scene_light_irradiance(patch_position, -n);  // transmission
    out_texel = vec4(lambert_radiance(draw.albedo.rgb * colour, irradiance, 1.0, frame.ambient.rgb), 1.0);
    out_blades = vec4(threshold, threshold, root);
}
