// How an image-based representation's fragment turns a baked texel, filtered or not
// (blade_texels.h), into what it draws: the share of the texel the blades cover, times the share
// of those blades its density and band keep (read at the blades' root, as the blades are thinned;
// across grass.lod's smooth transitions, a screen door), made coverage by alpha-to-coverage where
// grass.lod's `coverage` asks for it (under MSAA) and else by an alpha test at a_r
// (GRASS_ALPHA_REFERENCE). With no filter
// (mip_filter = "none") a texel's alpha is 0 or 1 and this is the binary cut of before.
#include "blade_texels.h"
#include "blade_coverage.h"
#include "grass_density.h"
#include "grass_lod_band.glsl"

// The texel's alpha for a representation drawing `band` of the blades, the cell's corner
// `densities` (grass_root_density): the covered share times the share of its blades the density
// and band keep (blade_texel_share). Inside grass.lod with a smooth transition, the share its band
// keeps is drawn instead as a screen door: the covered share times the share the density keeps,
// on the pixels whose screen-door value lies in the band's part (blade_texel_interval); the
// bands' parts tile what the density keeps, so each pixel of a texel is drawn by one band.
// Needs grass_lod_band.glsl.
float grass_slice_alpha(vec4 colour, vec4 blades, vec4 densities, vec2 band) {
    float ld = grass_root_density(densities, blades.zw);
#ifdef GRASS_LOD_REPRESENTATION
    if (grass_transition_window() != GRASS_LOD_WINDOW_BINARY && grass_transition_width() > 0.0) {
        float kept = blade_texel_share(blades.xy, ld, vec2(0.0, 1.0));
        if (!(kept > 0.0)) return 0.0;
        vec2 interval = blade_texel_interval(blades.xy, ld, band, grass_transition_window(), grass_transition_width());
        return lod_interval_draws(interval, kept * lod_screen_door(gl_FragCoord.xy)) ? colour.a * kept : 0.0;
    }
#endif
    return colour.a * blade_texel_share(blades.xy, ld, band);
}

// The fragment's output alpha, discarding what shows nothing: the alpha itself under
// alpha-to-coverage, else 1 where the alpha test at a_r passes.
float grass_slice_coverage(float alpha) {
#ifdef GRASS_LOD_REPRESENTATION
    if (frame.technique.coverage == GRASS_COVERAGE_ALPHA_TO_COVERAGE) {
        if (!(alpha > 0.0)) discard;
        return min(alpha, 1.0);
    }
#endif
    if (!(alpha > GRASS_ALPHA_REFERENCE)) discard;
    return 1.0;
}

// A filtered baked normal made unit again (the mips average normals; level 0's are unit), up
// where the average cancels out.
vec3 grass_slice_normal(vec3 filtered) {
    float length_squared = dot(filtered, filtered);
    return length_squared > 1e-12 ? filtered * inversesqrt(length_squared) : vec3(0.0, 1.0, 0.0);
}
