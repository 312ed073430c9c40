// The mip filters of grass slices (shaders/mip_filters.h, common/mip_chain.hpp): each equation
// on four texels, at its extremes (all transparent, all opaque); and on whole pyramids of a sparse
// blade-like mask, what the theses argue about: the box filter's alpha test loses the blades
// level by level (Lemme Fig. 4.8), the max-alpha filter's keeps too many (L439), and the
// coverage-preserving filter keeps no more than max-alpha and no fewer than level 0's share
// rounded to the level's texels, closer to level 0 than max-alpha where level 0 has partial
// alphas, and exactly max-alpha's where it has none. A filter that averages
// alpha where it should take the maximum, or skips the rescaling, fails a check here.
#include "support/bake_truth.hpp"

#include "../common/mip_chain.hpp"
#include "../shaders/mip_filters.h"

#include "run/family_benchmark.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace canopy;
using grass::MipFilter;

namespace {

// A size x size mask of thin slanted strokes (blade-like: 1 to 3 texels wide), colour varying,
// covering about `share` of the texels; transparent texels carry a colour of their own (the
// bake's clear), which no filter may let through.
// `supersampling` s > 1: drawn s times finer and box-filtered down, so level 0 has partial alphas
// along the strokes' edges, as an anti-aliased bake would (Lemme L514).
grass::RgbaLevel strokes(uint32_t size, double share, uint32_t seed, uint32_t supersampling = 1) {
    if (supersampling > 1) return grass::resolve_supersampled(strokes(size * supersampling, share, seed), supersampling);
    grass::RgbaLevel level{size, size, std::vector<glm::vec4>(size_t(size) * size, glm::vec4(1, 0, 1, 0))};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    size_t covered = 0;
    while (double(covered) < share * double(level.texels.size())) {
        const float x0 = unit(rng) * float(size), y0 = unit(rng) * float(size), slope = unit(rng) - 0.5f;
        const int width = 1 + int(unit(rng) * 3.0f), length = int(size / 4);
        const glm::vec4 colour(0.1f + 0.2f * unit(rng), 0.5f + 0.4f * unit(rng), 0.1f, 1.0f);
        for (int t = 0; t < length; ++t)
            for (int w = 0; w < width; ++w) {
                const int x = int(x0 + slope * float(t)) + w, y = int(y0) + t;
                if (x < 0 || y < 0 || x >= int(size) || y >= int(size)) continue;
                glm::vec4& texel = level.texels[size_t(y) * size + size_t(x)];
                covered += texel.w == 0.0f;
                texel = colour;
            }
    }
    return level;
}

}  // namespace

TEST_CASE("mip filters: each equation on four texels") {
    const glm::vec4 green(0, 1, 0, 1), clear(1, 0, 1, 0), half_red(1, 0, 0, 0.5f), blue(0, 0, 1, 1);
    // Eq 4.7-4.8: plain means, the clear colour bleeding in.
    CHECK(shader::mip_box(green, clear, clear, clear) == glm::vec4(0.75f, 0.25f, 0.75f, 0.25f));
    // Eq 4.9-4.10 (B eq 4.17-4.18): the clear colour has no weight; max alpha.
    const glm::vec4 m = shader::mip_max_alpha(green, clear, half_red, blue);
    CHECK(m.x == doctest::Approx(0.5f / 2.5f));
    CHECK(m.y == doctest::Approx(1.0f / 2.5f));
    CHECK(m.z == doctest::Approx(1.0f / 2.5f));
    CHECK(m.w == 1.0f);
    // All transparent: s_a = 1, a colour of 0 and alpha 0, not 0 / 0.
    const glm::vec4 empty = shader::mip_max_alpha(clear, clear, clear, clear);
    CHECK(empty == glm::vec4(0.0f));
    // All opaque: the mean colour, alpha 1.
    CHECK(shader::mip_max_alpha(green, green, blue, blue) == glm::vec4(0, 0.5f, 0.5f, 1));
    // Eq 4.14-4.15: alpha scaled and kept in [0, 1], colour untouched.
    CHECK(shader::mip_scale_alpha(half_red, 1.5f) == glm::vec4(1, 0, 0, 0.75f));
    CHECK(shader::mip_scale_alpha(half_red, 4.0f).w == 1.0f);
    CHECK(shader::mip_scale_alpha(half_red, 0.0f).w == 0.0f);
    // Eq 4.16: the transparent share takes the next level's colour.
    CHECK(shader::mip_bleed(half_red, glm::vec4(0, 1, 0, 1)) == glm::vec4(0.5f, 0.5f, 0, 0.5f));
    CHECK(shader::mip_bleed(clear, green) == glm::vec4(0, 1, 0, 0));
}

TEST_CASE("mip filters: coverage and its reference a'_r (eq 4.11, 4.13)") {
    grass::RgbaLevel level{4, 1, {glm::vec4(0, 0, 0, 0.9f), glm::vec4(0, 0, 0, 0.2f), glm::vec4(0, 0, 0, 0.6f),
                                  glm::vec4(0, 0, 0, 0.0f)}};
    CHECK(grass::alpha_coverage(level, 0.5f) == 0.5);
    CHECK(grass::alpha_coverage(level, 0.95f) == 0.0);
    CHECK(grass::alpha_coverage(grass::RgbaLevel{}, 0.5f) == 0.0);
    for (double share : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        CAPTURE(share);
        const float reference = grass::coverage_reference(level, share);
        // Texels equal to 0 never pass (strictly above a'_r >= 0): 3 of 4 at most.
        CHECK(grass::alpha_coverage(level, reference) == doctest::Approx(std::min(share, 0.75)));
    }
}

TEST_CASE("mip filters: pyramids of a sparse blade mask, as the theses argue") {
    const float a_r = 0.5f;
    for (uint32_t supersampling : {1u, 4u})
        for (double share : {0.08, 0.25, 0.5}) {
            CAPTURE(supersampling);
            CAPTURE(share);
            const grass::RgbaLevel base = strokes(256, share, 9, supersampling);
            const double c0 = grass::alpha_coverage(base, a_r);
            double mean0 = 0;
            for (const glm::vec4& t : base.texels) mean0 += t.w;
            mean0 /= double(base.texels.size());
            const auto box = grass::mip_chain(base, MipFilter::box, a_r);
            const auto max_alpha = grass::mip_chain(base, MipFilter::max_alpha, a_r);
            const auto preserving = grass::mip_chain(base, MipFilter::coverage, a_r);
            REQUIRE(box.size() == 9);  // 256 .. 1
            REQUIRE(max_alpha.size() == 9);
            REQUIRE(preserving.size() == 9);
            double closer = 0, farther = 0;
            for (size_t l = 1; l < 9; ++l) {
                CAPTURE(l);
                CHECK(box[l].width == 256u >> l);
                // The box keeps the mean alpha exactly (up to rounding) ...
                double mean = 0;
                for (const glm::vec4& t : box[l].texels) mean += t.w;
                CHECK(mean / double(box[l].texels.size()) == doctest::Approx(mean0).epsilon(1e-4));
                // ... the max-alpha filter never loses a blade's texel and, once texels merge
                // blades and gaps, keeps more than level 0 (Lemme L439: "a little over ... opaque").
                const double over = grass::alpha_coverage(max_alpha[l], a_r);
                CHECK(over >= c0);
                if (l >= 2 && l <= 5) CHECK(over > c0 + 0.05);
                // The coverage-preserving filter never keeps less than level 0 nor more than
                // max-alpha; an alpha test cannot split tied alphas, so on a mask whose level 0
                // is all 0 or 1 (max-alpha levels are too) it keeps exactly what max-alpha keeps.
                const double kept = grass::alpha_coverage(preserving[l], a_r);
                CHECK(kept >= c0 - 1.0 / double(preserving[l].texels.size()));
                CHECK(kept <= over + 1e-9);
                const bool some = std::llround(c0 * double(preserving[l].texels.size())) >= 1;
                if (supersampling == 1 && some) CHECK(kept == over);
                if (l <= 5) {
                    closer += std::abs(kept - c0);
                    farther += std::abs(over - c0);
                }
                for (const auto* chain : {&box, &max_alpha, &preserving})
                    for (const glm::vec4& t : (*chain)[l].texels) {
                        REQUIRE(std::isfinite(t.x + t.y + t.z + t.w));
                        REQUIRE(t.w >= 0.0f);
                        REQUIRE(t.w <= 1.0f);
                    }
            }
            CAPTURE(closer);
            CAPTURE(farther);
            // With partial alphas to rescale, it keeps closer to level 0 than max-alpha does.
            if (supersampling > 1) CHECK(closer < 0.8 * farther);
            // The box's alpha test loses a sparse mask: "grass ... seems to disappear" (L423, Fig. 4.8).
            if (share < 0.3) CHECK(grass::alpha_coverage(box[4], a_r) < 0.5 * c0);
            // No filter lets the clear colour through where it weighs colour by alpha.
            for (const glm::vec4& t : max_alpha[3].texels) CHECK(!(t.x > 0.9f && t.z > 0.9f));
        }
}

TEST_CASE("mip filters: a supersampled bake resolves to the covered share and the blades' own colour") {
    const grass::RgbaLevel fine{4, 2, {glm::vec4(0, 1, 0, 1), glm::vec4(0), glm::vec4(0), glm::vec4(1, 0, 0, 1),
                                       glm::vec4(0), glm::vec4(0), glm::vec4(0), glm::vec4(1, 0, 0, 1)}};
    const grass::RgbaLevel level = grass::resolve_supersampled(fine, 2);
    REQUIRE(level.width == 2);
    REQUIRE(level.height == 1);
    CHECK(level.texels[0] == glm::vec4(0, 1, 0, 0.25f));
    CHECK(level.texels[1] == glm::vec4(1, 0, 0, 0.5f));
    CHECK(grass::resolve_supersampled(fine, 1).texels == fine.texels);
    CHECK_THROWS_AS(grass::resolve_supersampled(fine, 3), std::invalid_argument);
}

TEST_CASE("mip filters: extremes stay finite and in range") {
    for (const float alpha : {0.0f, 1.0f}) {
        CAPTURE(alpha);
        const grass::RgbaLevel flat{8, 4, std::vector<glm::vec4>(32, glm::vec4(0.2f, 0.7f, 0.1f, alpha))};
        for (const MipFilter f : grass::kMipFilters)
            for (bool bleed : {false, true}) {
                const auto chain = grass::mip_chain(flat, f, 0.5f, bleed);
                REQUIRE(chain.size() == 4);  // 8x4, 4x2, 2x1, 1x1
                CHECK(chain.back().width == 1);
                CHECK(chain.back().height == 1);
                for (const auto& level : chain)
                    for (const glm::vec4& t : level.texels) {
                        REQUIRE(std::isfinite(t.x + t.y + t.z + t.w));
                        CHECK(t.w == alpha);
                    }
            }
    }
    // A 1 x 1 level is its own pyramid; an odd side drops its last texel, as Vulkan sizes mips.
    CHECK(grass::mip_chain(grass::RgbaLevel{1, 1, {glm::vec4(1)}}, MipFilter::coverage, 0.5f).size() == 1);
    const grass::RgbaLevel odd{3, 1, {glm::vec4(0), glm::vec4(0), glm::vec4(0, 1, 0, 1)}};
    const grass::RgbaLevel reduced = grass::reduce(odd, MipFilter::max_alpha);
    CHECK(reduced.width == 1);
    CHECK(reduced.texels[0].w == 0.0f);  // texels 0 and 1: Vulkan's floor(3 / 2) drops the last
    CHECK_THROWS_AS(grass::reduce(grass::RgbaLevel{2, 2, {}}, MipFilter::box), std::invalid_argument);
}

TEST_CASE("mip filters: colour bleeding fills transparent texels from the level above, opaque ones keep theirs") {
    const grass::RgbaLevel base = strokes(64, 0.2, 4);
    const auto bled = grass::mip_chain(base, MipFilter::max_alpha, 0.5f, true);
    const auto plain = grass::mip_chain(base, MipFilter::max_alpha, 0.5f, false);
    int filled = 0;
    for (size_t i = 0; i < base.texels.size(); ++i) {
        const glm::vec4 &b = bled[0].texels[i], &p = plain[0].texels[i];
        if (p.w == 1.0f) CHECK(b == p);
        if (p.w == 0.0f) {
            CHECK(b.w == 0.0f);
            CHECK(!(b.x > 0.9f && b.z > 0.9f));  // not the clear colour
            filled += b.y > 0.3f;                 // a blade's green from above
        }
    }
    CHECK(filled > int(base.texels.size()) / 2);
}

TEST_CASE("mip filters: `canopy bench mip-coverage` measures the slices the techniques bake") {
    const FamilyBenchmark* bench = nullptr;
    for (const FamilyBenchmark* b : FamilyBenchmarkRegistry::instance().all())
        if (b->name() == "mip-coverage") bench = b;
    REQUIRE(bench);
    const Scene scene = grass::test::one_cell_scene("[camera]\nposition = [0.5, 1, 2.5]\ntarget = [0.5, 0, 0.5]", "density = 1.0");
    const ParamSet params = ParamSet::resolve(bench->params(),
                                              {{"resolution", 32LL}, {"slices", 2LL}, {"slice_resolution", 32LL},
                                               {"height_resolution", 8LL}, {"supersampling", 2LL}, {"view_width", 64LL},
                                               {"views", 2LL}},
                                              {}, {}, "bench");
    const FamilyBenchmarkResult result = bench->run(test::gpu(), scene, params);
    CHECK(result.markdown.find("coverage-preserving") != std::string::npos);
    int sources = 0;
    for (const auto& [label, source] : result.numbers.items()) {
        if (label == "alpha_reference") continue;
        if (label == "views_against_blades") {
            // Every representation under every filter at every elevation, against the blades.
            REQUIRE(source.size() == 4);
            for (const auto& [technique, settings] : source.items()) {
                CAPTURE(technique);
                CHECK(settings.size() == 5);
                for (const auto& [setting, cells] : settings.items()) {
                    CAPTURE(setting);
                    REQUIRE(cells.size() == 2);
                    for (const auto& cell : cells) {
                        CHECK(cell.at("pixels").get<long long>() > 0);
                        CHECK(std::isfinite(cell.at("bias").get<double>()));
                        CHECK(cell.at("tile_mae").get<double>() >= 0.0);
                    }
                }
            }
            continue;
        }
        ++sources;
        CAPTURE(label);
        const double base = source.at("base_coverage").get<double>();
        CHECK(base > 0.02);
        CHECK(base < 0.9);
        const auto& levels = source.at("levels");
        REQUIRE(levels.size() >= 4);  // 32 x 32 -> 1 x 1, or 32 x 8 -> 1 x 1
        for (size_t l = 0; l < levels.size(); ++l) {
            CAPTURE(l);
            const double box = levels[l].at("box").at("coverage"), over = levels[l].at("max-alpha").at("coverage");
            const double kept = levels[l].at("coverage-preserving").at("coverage");
            if (l == 0) {
                CHECK(box == base);
                CHECK(over == base);
                CHECK(kept == base);
            }
            CHECK(over >= base);
            CHECK(kept <= over);
            CHECK(double(levels[l].at("box").at("mean_alpha")) == doctest::Approx(double(levels[0].at("box").at("mean_alpha"))).epsilon(1e-3));
        }
    }
    CHECK(sources == 2);
}
