// The load-phase passes that give a baked grass slice array its mips (shaders/blade_texels.h):
// the bake renders `supersampling` times finer than the slice's resolution; after it has written
// that fine level of its colour, blade map and companion (a normal, or a BTF slice's lit rows),
// each next level is reduced from the one above on the GPU (shaders/grass_mip_reduce.glsl): first
// resolved down to the slice's resolution (the covered share, the alpha-weighted colour: an
// anti-aliased level 0, as Lemme L514's "anti-aliased renderer"), then by the chosen filter (with
// Lemme's, shaders/grass_mip_coverage.comp rescales each level to the resolved level's coverage);
// then the levels are bled from the smallest up (shaders/grass_mip_bleed.glsl). The frame passes
// sample from the resolved level on. common/mip_chain.cpp is the same arithmetic on the CPU,
// which the tests hold these levels to. Every image-based representation (volume, slices, image,
// billboards) declares its bake's chain with it.
#pragma once

#include "mip_chain.hpp"

#include "core/technique.hpp"
#include "graph/frame_graph.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace canopy::grass {

// How a representation's slices are baked and filtered when drawn.
struct SliceFiltering {
    // none: the resolved level alone with NEAREST (with supersampling 1, canopy's representations
    // before issue 37: a texel is one blade or none); else the chain is built with this filter
    // and sampled trilinearly.
    std::optional<MipFilter> filter = MipFilter::coverage;
    bool bleed = true;            // Lemme's colour bleeding (eq 4.16) of the colour and companion
    bool anisotropic = false;     // up to 16 trilinear lookups along a stretched footprint (canopy's)
    uint32_t supersampling = 2;   // the bake's texels per slice texel, each way: 1, 2 or 4

    uint32_t resolve_levels() const;  // log2(supersampling): the level the frame passes start at
};

// From the parameters shaders/slice_filtering_params.h declares.
SliceFiltering slice_filtering(const ParamSet& params);
// A refused combination of those parameters: bake_supersampling not a power of 2.
std::optional<ParamConflict> slice_filtering_conflict(const ParamSet& params);

// The levels a bake of width x height slice texels is declared with: the fine level, the resolve
// levels and, with a filter, the chain down to 1 x 1. Its level 0 is width x height times
// supersampling (bake_extent).
uint32_t mip_levels(uint32_t width, uint32_t height, const SliceFiltering& filtering);
ImageExtent bake_extent(uint32_t width, uint32_t height, const SliceFiltering& filtering);

// The frame passes' read of a baked image: from the resolved level on, trilinear (or anisotropic)
// over the chain, or NEAREST.
ResourceUse sampled_slices(const std::string& image, int binding, const SliceFiltering& filtering);

struct SliceMipChain {
    std::string colour;  // RGBA32F: rgb colour, alpha coverage
    std::string blades;  // RGBA32F: blade map
    // RGBA16F, `companions` layers per colour layer, weighted by the colour's coverage (a normal;
    // a BTF slice's lit rows); none where empty.
    std::string companion;
    uint32_t companions = 1;
    uint32_t width = 0, height = 0, layers = 1;  // the slice's texels (not the bake's) and the colour's layers
    SliceFiltering filtering;
    std::string pass_prefix;  // before the passes' names
};

// The passes; the three images must be declared with bake_extent and mip_levels.
void declare_mip_passes(FrameGraph& g, const SliceMipChain& chain);

}  // namespace canopy::grass
