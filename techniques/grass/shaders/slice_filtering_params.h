// The parameters every image-based grass representation (grass.volume, grass.slices, grass.image,
// grass.billboard, and grass.lod for its bands) takes for how its baked slices are filtered
// (common/mip_passes.hpp, blade_texels.h): one declaration for all, inside each technique's
// parameter block, with the filter its thesis uses by default (Lemme's coverage-preserving
// filter for his volume and image, Boulanger's max-alpha for his BTF slices).
#ifndef CANOPY_GRASS_SLICE_FILTERING_PARAMS_H
#define CANOPY_GRASS_SLICE_FILTERING_PARAMS_H

#define GRASS_SLICE_FILTERING_PARAMS(PLAN, DEFAULT_FILTER)                                                                        \
    PLAN(integer, bake_supersampling, (2, 1, 4),                                                                   \
         "the bake's texels per slice texel each way (1, 2 or 4), resolved to the slice's resolution at load: each texel holds the share of it blades cover (an anti-aliased bake, Lemme L514), which Lemme's coverage-preserving filter needs (with 1, a texel is one blade or none and his filter keeps what max_alpha keeps)") \
    PLAN(choice, mip_filter, (DEFAULT_FILTER, {"coverage", "max_alpha", "box", "none"}),                                \
         "how the baked slices are filtered: coverage, Lemme's coverage-preserving mips (eq 4.9-4.15); max_alpha, Boulanger's (eq 4.16-4.18); box, the mean (Lemme eq 4.7-4.8); each sampled trilinearly, its alpha made coverage (alpha-to-coverage under MSAA, else an alpha test at 0.5); none: the resolved level alone with NEAREST (with bake_supersampling = 1, each texel one blade or none: canopy before issue 37)") \
    PLAN(boolean, mip_bleed, (true),                                                                               \
         "Lemme's colour bleeding (eq 4.16): a texel's transparent part takes the next level's colour and normal, so filtered lookups at a blade's edge show no clear colour (the blade map is bled whatever this says)") \
    PLAN(boolean, mip_anisotropic, (false),                                                                        \
         "sample the mips anisotropically (up to 16 trilinear lookups along a footprint stretched at grazing angles, where the device offers it) instead of trilinearly (the theses): canopy's addition")

#endif
