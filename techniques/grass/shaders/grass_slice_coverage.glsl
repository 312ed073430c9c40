// How an image-based representation's fragment turns a baked texel, filtered or not
// (blade_texels.h), into what it draws: the share of the texel the blades cover, times the share
// of those blades its density and band keep (the density read at the blades' root, as the blades
// are thinned), made coverage by alpha-to-coverage where grass.lod's `coverage` asks for it
// (under MSAA) and else by an alpha test at a_r (GRASS_ALPHA_REFERENCE). With no filter
// (mip_filter = "none") a texel's alpha is 0 or 1 and this is the binary cut of before.
#include "blade_texels.h"
#include "blade_coverage.h"
#include "grass_density.h"

// The texel's alpha for a representation drawing `band` of the blades, the cell's corner
// `densities` (grass_root_density).
float grass_slice_alpha(vec4 colour, vec4 blades, vec4 densities, vec2 band) {
    float ld = grass_root_density(densities, blades.zw);
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
