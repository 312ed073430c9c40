// The BTF slices' fragment stage (grass.slices; Boulanger Algorithm 1 and 4, eq 4.2): the slice's
// threshold texel is cut where it exceeds the cell's density at the fragment's ground point
// (Figure 4.9) or lies outside the representation's band (grass_lod_band.glsl); else the
// fragment shows the ambient row lit by the ambient light plus the light-weighted sum of the
// baked rows (renormalised: the weights are interpolated from the vertices) times the light's
// irradiance, by the family's one model (btf_radiance). Level-0 texels show a blade or none, so
// the slices are cut, not blended, and the depth test orders them. A row's alpha is its light's
// baked visibility (1 unless the bake was shadowed), thinned by the cell's density (eq 4.7).
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "grass_density.h"
#include "btf_interpolation.h"
#include "bake_shadows.h"

layout(set = 0, binding = 1) uniform sampler2DArray slices_albedo;  // NEAREST: thresholds are not blended
layout(set = 0, binding = 2) uniform sampler2DArray slices_lit;     // NEAREST
layout(set = 0, binding = 3) uniform sampler2D top_albedo;          // NEAREST
layout(set = 0, binding = 4) uniform sampler2DArray top_lit;        // NEAREST

layout(location = 0) in vec2 uv;
layout(location = 1) in vec2 patch_xz;
layout(location = 2) in vec4 weights0123;
layout(location = 3) in float weight4;
layout(location = 4) in vec3 light_irradiance;
layout(location = 5) flat in vec4 densities;
layout(location = 6) flat in ivec2 layer;
layout(location = 7) flat in vec2 band;
layout(location = 0) out vec4 out_color;

vec3 baked_row(int row, float density) {
    vec4 texel = layer.x < 0 ? texture(top_lit, vec3(uv, float(row))) : texture(slices_lit, vec3(uv, float(layer.y + row)));
    return texel.rgb * bake_shadow_at_density(texel.a, density);
}

void main() {
    vec4 albedo = layer.x < 0 ? texture(top_albedo, uv) : texture(slices_albedo, vec3(uv, float(layer.x)));
    float density = grass_root_density(densities, patch_xz);
    if (!grass_blade_in_band(albedo.a, density, band)) discard;
    float sum = weights0123.x + weights0123.y + weights0123.z + weights0123.w + weight4;
    vec3 rows = vec3(0.0);
    // At most three weights are not zero (App. A): only their rows are read.
    for (int row = 0; row < BTF_LIGHTS; ++row) {
        float w = row < 4 ? weights0123[row] : weight4;
        if (w > 0.0) rows += w * baked_row(row, density);
    }
    rows /= max(sum, 1e-6);
    out_color = vec4(btf_radiance(albedo.rgb, rows, light_irradiance, frame.ambient.rgb), 1.0);
}
