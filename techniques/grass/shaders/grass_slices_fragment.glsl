// The BTF slices' fragment stage (grass.slices; Boulanger Algorithm 1 and 4, eq 4.2): the slice's
// texel, filtered (common/mip_passes.hpp), keeps the share of its blades whose threshold the
// cell's density at their root reaches (Figure 4.9) within the representation's band
// (grass_lod_band.glsl), made coverage by grass_slice_coverage.glsl (alpha-to-coverage under
// MSAA, as Boulanger's "full-screen anti-aliasing", else an alpha test), so the slices are cut,
// not blended, and the depth test orders them; the fragment shows the ambient row lit by the
// ambient light plus the light-weighted sum of the baked rows (renormalised: the weights are
// interpolated from the vertices) times the light's irradiance, by the family's one model
// (btf_radiance). A row's alpha is its light's baked visibility (1 unless the bake was
// shadowed), thinned by the density at the blades' root (eq 4.7).
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "grass_density.h"
#include "btf_interpolation.h"
#include "bake_shadows.h"
#include "grass_slice_coverage.glsl"
#include "grass_lod_band.glsl"

// Trilinear (or NEAREST: mip_filter = "none"); the horizontal slice's are one-layer arrays.
layout(set = 0, binding = 1) uniform sampler2DArray slices_albedo;
layout(set = 0, binding = 2) uniform sampler2DArray slices_lit;
layout(set = 0, binding = 3) uniform sampler2DArray top_albedo;
layout(set = 0, binding = 4) uniform sampler2DArray top_lit;
layout(set = 0, binding = 8) uniform sampler2DArray slices_blades;  // blade_texels.h
layout(set = 0, binding = 9) uniform sampler2DArray top_blades;

layout(location = 0) in vec2 uv;
layout(location = 2) in vec4 weights0123;
layout(location = 3) in float weight4;
layout(location = 4) in vec3 light_irradiance;
layout(location = 5) flat in vec4 densities;
layout(location = 6) flat in ivec2 layer;
layout(location = 7) flat in mat4 model;  // locations 7-10: where a blade's root is (grass_lod_band.glsl)
layout(location = 0) out vec4 out_color;

// Read with the footprint taken before the rows' loop (its branches are not uniform control flow).
vec3 baked_row(int row, float density, vec2 dx, vec2 dy) {
    vec4 texel = layer.x < 0 ? textureGrad(top_lit, vec3(uv, float(row)), dx, dy)
                             : textureGrad(slices_lit, vec3(uv, float(layer.y + row)), dx, dy);
    return texel.rgb * bake_shadow_at_density(texel.a, density);
}

void main() {
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    vec4 albedo, blades;
    if (layer.x < 0) {
        albedo = textureGrad(top_albedo, vec3(uv, 0.0), dx, dy);
        blades = textureGrad(top_blades, vec3(uv, 0.0), dx, dy);
    } else {
        albedo = textureGrad(slices_albedo, vec3(uv, float(layer.x)), dx, dy);
        blades = textureGrad(slices_blades, vec3(uv, float(layer.x)), dx, dy);
    }
    float coverage = grass_slice_coverage(grass_slice_alpha(albedo, blades, densities, grass_blade_band(model, blades.zw)));
    float density = grass_root_density(densities, blades.zw);
    float sum = weights0123.x + weights0123.y + weights0123.z + weights0123.w + weight4;
    vec3 rows = vec3(0.0);
    // At most three weights are not zero (App. A): only their rows are read.
    for (int row = 0; row < BTF_LIGHTS; ++row) {
        float w = row < 4 ? weights0123[row] : weight4;
        if (w > 0.0) rows += w * baked_row(row, density, dx, dy);
    }
    rows /= max(sum, 1e-6);
    out_color = vec4(btf_radiance(albedo.rgb, rows, light_irradiance, frame.ambient.rgb), coverage);
}
