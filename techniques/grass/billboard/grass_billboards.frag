#version 450
#extension GL_GOOGLE_include_directive : require
// grass.billboard: the baked radiance, filtered (common/mip_passes.hpp), where the baked blades'
// thresholds are within the cell's density at their root, made coverage by an alpha test
// (grass_slice_coverage.glsl).
#include "grass_billboard_params.h"
#include "frame_uniforms.glsl"
#include "grass_slice_coverage.glsl"

layout(set = 0, binding = 1) uniform sampler2DArray billboard;  // trilinear, or NEAREST (mip_filter = "none")
layout(set = 0, binding = 8) uniform sampler2DArray billboard_blades;  // the same (blade_texels.h)

layout(location = 0) in vec2 uv;
layout(location = 1) flat in float layer;
layout(location = 2) flat in vec4 densities;
layout(location = 0) out vec4 out_color;

void main() {
    vec4 texel = texture(billboard, vec3(uv, layer));
    float alpha = grass_slice_alpha(texel, texture(billboard_blades, vec3(uv, layer)), densities, vec2(0.0, 1.0));
    out_color = vec4(texel.rgb, grass_slice_coverage(alpha));
}
