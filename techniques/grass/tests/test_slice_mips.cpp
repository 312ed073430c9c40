// The mips a representation's bake is given at load (common/mip_passes.hpp), level by level
// against the CPU: the supersampled bake resolved (mip_chain.cpp's resolve_supersampled), then the
// chosen filter (mip_chain.cpp's mip_chain, the coverage rescale and colour bleeding included),
// the blade map's own rule and bleeding (shaders/blade_texels.h) and the normal weighted by
// coverage (mip_filters.h's mip_companion); on a square top view (grass.image) and on slices
// whose sides are odd at some level (grass.volume). And the rule a filtered texel is drawn by
// (blade_texel_share): exact at level 0, additive over grass.lod's bands, the expected share where
// a footprint's thresholds are uniform. A pass skipped, run in the wrong order, dispatched over
// too few layers or reading the wrong level fails here.
#include "support/bake_truth.hpp"

#include "../common/mip_chain.hpp"
#include "../shaders/blade_texels.h"
#include "../shaders/lod_selection.h"
#include "../shaders/mip_filters.h"

#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace canopy;

namespace {

const char* kCamera = "[camera]\nposition = [0.5, 1.0, 2.5]\ntarget = [0.5, 0.0, 0.5]";

grass::RgbaLevel level_of(const Image& image) {
    grass::RgbaLevel level{uint32_t(image.width), uint32_t(image.height), {}};
    level.texels.resize(size_t(image.width) * size_t(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* t = image.at(x, y);
            level.texels[size_t(y) * size_t(image.width) + size_t(x)] = glm::vec4(t[0], t[1], t[2], t[3]);
        }
    return level;
}

// A level of a companion or blade map from the four texels each next texel covers (as reduce).
template <typename Reduce>
grass::RgbaLevel reduce_with(const grass::RgbaLevel& level, const grass::RgbaLevel& alphas, Reduce f) {
    grass::RgbaLevel next{std::max(1u, level.width / 2), std::max(1u, level.height / 2), {}};
    next.texels.resize(size_t(next.width) * next.height);
    for (uint32_t y = 0; y < next.height; ++y)
        for (uint32_t x = 0; x < next.width; ++x) {
            const uint32_t x0 = std::min(2 * x, level.width - 1), x1 = std::min(2 * x + 1, level.width - 1);
            const uint32_t y0 = std::min(2 * y, level.height - 1), y1 = std::min(2 * y + 1, level.height - 1);
            const glm::vec4 a(alphas.at(x0, y0).w, alphas.at(x1, y0).w, alphas.at(x0, y1).w, alphas.at(x1, y1).w);
            next.texels[size_t(y) * next.width + x] =
                f(level.at(x0, y0), level.at(x1, y0), level.at(x0, y1), level.at(x1, y1), a);
        }
    return next;
}

struct Chains {
    std::vector<grass::RgbaLevel> colour, blades, normal;  // from the resolved level down
};

// The CPU's chains from a bake's fine level (colour, blade map, normal), as mip_passes.cpp
// declares them: `resolve` halvings, then `filter`; bled from the smallest level up.
Chains cpu_chains(const grass::RgbaLevel& colour, const grass::RgbaLevel& blades, const grass::RgbaLevel& normal,
                  uint32_t resolve, grass::MipFilter filter, bool bleed) {
    grass::RgbaLevel c = colour, b = blades, n = normal;
    const auto companion = [](glm::vec4 t0, glm::vec4 t1, glm::vec4 t2, glm::vec4 t3, glm::vec4 a) {
        return shader::mip_companion(t0, t1, t2, t3, a);
    };
    const auto blade_rule = [](glm::vec4 t0, glm::vec4 t1, glm::vec4 t2, glm::vec4 t3, glm::vec4 a) {
        return shader::blade_map_reduce(t0, t1, t2, t3, a);
    };
    for (uint32_t r = 0; r < resolve; ++r) {
        const grass::RgbaLevel next_c = grass::resolve_supersampled(c, 2);
        b = reduce_with(b, c, blade_rule);
        n = reduce_with(n, c, companion);
        c = next_c;
    }
    Chains chains;
    chains.colour = grass::mip_chain(c, filter, shader::GRASS_ALPHA_REFERENCE, bleed);
    // The blade map and normal follow the unbled colour chain's alphas.
    const std::vector<grass::RgbaLevel> alphas = grass::mip_chain(c, filter, shader::GRASS_ALPHA_REFERENCE, false);
    chains.blades = {b};
    chains.normal = {n};
    for (size_t l = 0; l + 1 < alphas.size(); ++l) {
        chains.blades.push_back(reduce_with(chains.blades.back(), alphas[l], blade_rule));
        chains.normal.push_back(reduce_with(chains.normal.back(), alphas[l], companion));
    }
    for (size_t l = alphas.size() - 1; l-- > 0;) {
        grass::RgbaLevel& bl = chains.blades[l];
        grass::RgbaLevel& nl = chains.normal[l];
        const grass::RgbaLevel &bn = chains.blades[l + 1], &nn = chains.normal[l + 1];
        for (uint32_t y = 0; y < bl.height; ++y)
            for (uint32_t x = 0; x < bl.width; ++x) {
                const uint32_t qx = std::min(x / 2, bn.width - 1), qy = std::min(y / 2, bn.height - 1);
                glm::vec4& t = bl.texels[size_t(y) * bl.width + x];
                t = shader::blade_map_bleed(t, bn.at(qx, qy));
                if (bleed) {
                    glm::vec4& m = nl.texels[size_t(y) * nl.width + x];
                    m = shader::mip_bleed_companion(m, alphas[l].at(x, y).w, nn.at(qx, qy));
                }
            }
    }
    return chains;
}

// The largest difference of two levels' texels (the normal's in xyz, stored as 16-bit floats).
float max_difference(const grass::RgbaLevel& a, const grass::RgbaLevel& b, int channels = 4) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    float d = 0.0f;
    for (size_t i = 0; i < a.texels.size(); ++i)
        for (int c = 0; c < channels; ++c) d = std::max(d, std::abs(a.texels[i][c] - b.texels[i][c]));
    return d;
}

struct Case {
    const char* technique;
    std::map<std::string, ParamValue> params;
    const char *colour, *blades, *normal;
    uint32_t layers;
};

void check_chains(const Case& c, const std::string& filter_name, grass::MipFilter filter, bool bleed) {
    CAPTURE(c.technique);
    CAPTURE(filter_name);
    CAPTURE(bleed);
    const Scene scene = grass::test::one_cell_scene(kCamera, "density = 1.0");
    const Technique* t = TechniqueRegistry::instance().find(c.technique);
    REQUIRE(t);
    std::map<std::string, ParamValue> values = c.params;
    values["mip_filter"] = filter_name;
    values["mip_bleed"] = bleed;
    values["bake_supersampling"] = 2LL;
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), 32, 24,
                           t->graph(ParamSet::resolve(t->params(), values, {}, {}, c.technique)));
    renderer.render();
    for (uint32_t layer = 0; layer < c.layers; ++layer) {
        CAPTURE(layer);
        const Chains cpu = cpu_chains(level_of(renderer.read_image(c.colour, 0, layer)),
                                      level_of(renderer.read_image(c.blades, 0, layer)),
                                      level_of(renderer.read_image(c.normal, 0, layer)), 1, filter, bleed);
        REQUIRE(cpu.colour.size() >= 5);
        for (size_t l = 0; l < cpu.colour.size(); ++l) {
            CAPTURE(l);
            const uint32_t mip = uint32_t(l) + 1;  // the resolved level is mip 1
            const grass::RgbaLevel colour = level_of(renderer.read_image(c.colour, mip, layer));
            const grass::RgbaLevel blades = level_of(renderer.read_image(c.blades, mip, layer));
            const grass::RgbaLevel normal = level_of(renderer.read_image(c.normal, mip, layer));
            CHECK(max_difference(colour, cpu.colour[l]) <= 1e-4f);
            CHECK(max_difference(blades, cpu.blades[l]) <= 1e-5f);
            CHECK(max_difference(normal, cpu.normal[l], 3) <= 4e-3f);  // 16-bit floats
            for (const glm::vec4& texel : colour.texels)
                for (int k = 0; k < 4; ++k) REQUIRE(std::isfinite(texel[k]));
        }
    }
}

}  // namespace

TEST_CASE("slice mips: every level of grass.image's and grass.volume's bakes is the CPU's, for every filter") {
    const std::vector<Case> cases = {
        {"grass.image", {{"resolution", 32LL}}, "slice_albedo", "slice_blades", "slice_normal", 1},
        // 40 x 12 texels a slice (80 x 24 baked): levels of 5 x 1 and 2 x 1 drop an odd side's texel.
        {"grass.volume", {{"resolution", 40LL}, {"height_resolution", 12LL}, {"slices", 2LL}},
         "slices_albedo", "slices_blades", "slices_normal", 4},
    };
    for (const Case& c : cases) {
        check_chains(c, "box", grass::MipFilter::box, false);
        check_chains(c, "max_alpha", grass::MipFilter::max_alpha, true);
        check_chains(c, "coverage", grass::MipFilter::coverage, true);
    }
}

TEST_CASE("slice mips: the resolved level holds the share of each texel its blades cover") {
    const Scene scene = grass::test::one_cell_scene(kCamera, "density = 1.0");
    const Technique* t = TechniqueRegistry::instance().find("grass.image");
    REQUIRE(t);
    // The resolved level (mip 2 of a 4x bake) and a bake of one point per texel.
    const auto bake = [&](long long supersampling, uint32_t mip) {
        FrameRenderer r(test::gpu(), scene, build_scene_meshes(scene), 32, 24,
                        t->graph(ParamSet::resolve(t->params(),
                                                   {{"resolution", 64LL}, {"bake_supersampling", supersampling},
                                                    {"mip_filter", std::string("none")}},
                                                   {}, {}, "grass.image")));
        r.render();
        return r.read_image("slice_albedo", mip);
    };
    const Image resolved = bake(4, 2);
    const Image binary = bake(1, 0);
    REQUIRE(resolved.width == 64);
    double resolved_sum = 0, binary_sum = 0;
    int partial = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float a = resolved.at(x, y)[3];
            CHECK((a >= 0.0f && a <= 1.0f));
            partial += a > 0.0f && a < 1.0f;
            resolved_sum += a;
            binary_sum += binary.at(x, y)[3];
        }
    // Anti-aliased: blade edges are partly covered; the covered area is the same as a bake that
    // samples one point per texel, within the noise of that point sampling.
    CHECK(partial > 200);
    CAPTURE(resolved_sum);
    CAPTURE(binary_sum);
    CHECK(resolved_sum == doctest::Approx(binary_sum).epsilon(0.08));
}

TEST_CASE("slice mips: a filtered texel's share of its blades, exact at level 0 and additive over the bands") {
    using shader::blade_texel_share;
    // Level 0: one threshold, kept whole or not at all, as grass_blade_in_band keeps a blade.
    CHECK(blade_texel_share(glm::vec2(0.3f, 0.3f), 0.5f, glm::vec2(0.0f, 1.0f)) == 1.0f);
    CHECK(blade_texel_share(glm::vec2(0.6f, 0.6f), 0.5f, glm::vec2(0.0f, 1.0f)) == 0.0f);
    CHECK(blade_texel_share(glm::vec2(0.3f, 0.3f), 1.0f, glm::vec2(0.3f, 1.0f)) == 0.0f);  // (lo, hi]
    CHECK(blade_texel_share(glm::vec2(0.3f, 0.3f), 1.0f, glm::vec2(0.0f, 0.3f)) == 1.0f);
    // A range read as evenly filled: half of [0.2, 0.6] lies under 0.4.
    CHECK(blade_texel_share(glm::vec2(0.2f, 0.6f), 0.4f, glm::vec2(0.0f, 1.0f)) == doctest::Approx(0.5f));
    CHECK(blade_texel_share(glm::vec2(0.2f, 0.6f), 1.0f, glm::vec2(0.0f, 1.0f)) == 1.0f);
    CHECK(blade_texel_share(glm::vec2(0.2f, 0.6f), 0.0f, glm::vec2(0.0f, 1.0f)) == 0.0f);
    // grass.lod's three bands split every texel's share exactly, whatever the distance.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        float a = unit(rng), b = unit(rng);
        const glm::vec2 range(std::min(a, b), i % 3 == 0 ? std::min(a, b) : std::max(a, b));
        const float ld = unit(rng), d = 40.0f * unit(rng);
        const glm::vec2 cuts = shader::lod_cuts(d, 5.0f, 10.0f, 20.0f, 30.0f);
        float sum = 0.0f;
        for (int representation : {shader::GRASS_LOD_GEOMETRY, shader::GRASS_LOD_VOLUME, shader::GRASS_LOD_IMAGE}) {
            const float share = blade_texel_share(range, ld, shader::lod_band(representation, cuts));
            CHECK((share >= 0.0f && share <= 1.0f));
            sum += share;
        }
        CHECK(sum == doctest::Approx(blade_texel_share(range, ld, glm::vec2(0.0f, 1.0f))).epsilon(1e-5));
    }
}

TEST_CASE("slice mips: the blade map's mip rule keeps the thresholds' range and the roots' mean, and gives the share "
          "a footprint keeps in expectation") {
    const glm::vec4 empty = shader::BLADE_MAP_EMPTY;
    const glm::vec4 a(0.2f, 0.2f, 0.1f, 0.1f), b(0.7f, 0.7f, 0.3f, 0.5f);
    const glm::vec4 r = shader::blade_map_reduce(a, b, empty, empty, glm::vec4(1.0f, 0.5f, 0.0f, 0.0f));
    CHECK(r.x == 0.2f);
    CHECK(r.y == 0.7f);
    CHECK(r.z == doctest::Approx((0.1f * 1.0f + 0.3f * 0.5f) / 1.5f));
    CHECK(r.w == doctest::Approx((0.1f * 1.0f + 0.5f * 0.5f) / 1.5f));
    CHECK(shader::blade_map_reduce(empty, empty, empty, empty, glm::vec4(0.0f)) == empty);
    CHECK(shader::blade_map_bleed(empty, b) == b);
    CHECK(shader::blade_map_bleed(a, b) == a);
    // A footprint of 64 level-0 texels, each its own blade, thresholds uniform in ]0, 1]: the
    // reduced texel's share at density ld is the share of its blades ld keeps, but for the range's
    // ends (the smallest of n uniform thresholds lies at 1 / (n + 1) on average, the largest at
    // n / (n + 1)): within 1 / 65 and the sampling noise (measured: at most 0.014 below).
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (float ld : {0.1f, 0.3f, 0.5f, 0.8f}) {
        double kept = 0, drawn = 0;
        for (int footprint = 0; footprint < 400; ++footprint) {
            std::vector<glm::vec4> texels(64);
            for (glm::vec4& t : texels) {
                const float th = 1.0f - unit(rng);  // ]0, 1]
                t = glm::vec4(th, th, 0.5f, 0.5f);
                kept += th <= ld;
            }
            while (texels.size() > 1) {
                std::vector<glm::vec4> next;
                for (size_t i = 0; i < texels.size(); i += 4)
                    next.push_back(shader::blade_map_reduce(texels[i], texels[i + 1], texels[i + 2], texels[i + 3],
                                                            glm::vec4(1.0f)));
                texels = next;
            }
            drawn += 64.0 * shader::blade_texel_share(glm::vec2(texels[0]), ld, glm::vec2(0.0f, 1.0f));
        }
        CAPTURE(ld);
        CAPTURE(kept);
        CAPTURE(drawn);
        CHECK(std::abs(drawn - kept) / (400.0 * 64.0) <= 1.0 / 65.0 + 0.005);
    }
}
