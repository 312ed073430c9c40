// Mip pyramids of a slice (colour and alpha per texel) built with the filters of
// shaders/mip_filters.h, and the coverage Lemme compares them by (eq 4.11): the share of texels an
// alpha test at a_r keeps. CPU code: `canopy bench mip-coverage` measures the filters on baked
// slices with it, and the tests check it.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace canopy::grass {

enum class MipFilter {
    box,        // Lemme eq 4.7-4.8, Boulanger eq 4.15
    max_alpha,  // Boulanger eq 4.16-4.18
    coverage,   // Lemme eq 4.9-4.15: max alpha rescaled to level 0's coverage at a_r
};
const char* to_string(MipFilter filter);
inline constexpr MipFilter kMipFilters[] = {MipFilter::box, MipFilter::max_alpha, MipFilter::coverage};

struct RgbaLevel {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec4> texels;  // row-major: rgb colour, alpha
    const glm::vec4& at(uint32_t x, uint32_t y) const { return texels[size_t(y) * width + x]; }
};

// Eq 4.11: the share of texels whose alpha is above a_r (0 for an empty level).
double alpha_coverage(const RgbaLevel& level, float a_r);

// Eq 4.13: an alpha-test reference a'_r at which `level` keeps (strictly above it) the
// k = round(coverage x N) texels of largest alpha, and every texel tied with the k-th (Lemme is
// silent on ties: canopy keeps them, so a level never keeps fewer than k; an alpha test cannot
// split equal alphas, so a level whose alphas are all 0 or 1 keeps exactly what max-alpha keeps).
float coverage_reference(const RgbaLevel& level, double coverage);

// Level l + 1 from level l: each texel from the 2 x 2 it covers, max(1, size / 2) a side as
// Vulkan's mips (an odd side's last texel is dropped; a side of 1 texel is read twice).
RgbaLevel reduce(const RgbaLevel& level, MipFilter filter);

// A bake made `factor` times finer (a power of 2) brought to its level 0: each texel the mean alpha
// of its factor x factor subtexels (the share a blade covers) and their alpha-weighted colour, as
// an anti-aliased bake would hold (Lemme L514).
RgbaLevel resolve_supersampled(const RgbaLevel& fine, uint32_t factor);

// The whole pyramid down to 1 x 1, level 0 first. `coverage` rescales each level after its
// max-alpha reduction so it keeps level 0's coverage at a_r (Lemme: "always comparing with the
// base level coverage"); each level is reduced from the previous, rescaled one (Lemme is silent:
// canopy's choice, as Castaño's code does). `bleed`: Lemme's colour bleeding (eq 4.16) after,
// from the smallest level up.
std::vector<RgbaLevel> mip_chain(const RgbaLevel& base, MipFilter filter, float a_r, bool bleed = false);

}  // namespace canopy::grass
