// The blades' fragment stage (grass.geometry, grass.lod's near band): the blade outline
// (blade_alpha.h) cut by a hard alpha test, or ramped over a pixel for alpha-to-coverage, on the
// pixels of its share where it crosses a grass.lod transition (lod_band_interval); shaded
// by the family's one model with the blade's colour. Included after the technique's parameter
// block, which has `coverage`.
#include "frame_uniforms.glsl"
#include "draw_constants.glsl"
#include "blade_alpha.h"
#include "lod_selection.h"
#include "grass_shading.glsl"

layout(location = 0) centroid in vec3 world_position;
layout(location = 1) centroid in vec3 world_normal;
layout(location = 2) centroid in vec2 strip_uv;
layout(location = 3) centroid in float colour;
layout(location = 4) flat in float taper;
layout(location = 5) flat in vec2 transition;
layout(location = 0) out vec4 out_color;

void main() {
#ifdef GRASS_LOD_REPRESENTATION
    // A blade crossing a transition draws its share of the pixels (lod_selection.h).
    if (!lod_interval_draws(transition, lod_screen_door(gl_FragCoord.xy))) discard;
#endif
    float alpha = 1.0;
    if (frame.technique.coverage == GRASS_COVERAGE_ALPHA_TEST) {
        if (!blade_opaque(strip_uv, taper)) discard;
    } else {
        alpha = blade_alpha(strip_uv, taper, fwidth(strip_uv.x));
        if (alpha <= 0.0) discard;
    }
    out_color = grass_lit_output(draw.albedo.rgb * colour, world_position, world_normal, alpha, draw.albedo.w);
}
