// The field (common/grass_field.hpp) and its aperiodic tiling (shaders/cell_mirroring.h, Lemme
// eq 6.4-6.7): mirror signs per cell, geometry and slice coordinates mirrored alike, density
// maps, and the blades a field draws.
#include "../common/grass_field.hpp"
#include "../shaders/cell_mirroring.h"
#include "../shaders/grass_density.h"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <stdexcept>

using namespace canopy::grass;
namespace shader = canopy::shader;

TEST_CASE("grass tiling: each cell is one of the four mirrored versions, a quarter each, fixed by the seed") {
    std::array<int, 4> counts{};
    int same_as_right = 0;
    for (int z = -32; z < 32; ++z)
        for (int x = -32; x < 32; ++x) {
            const glm::vec2 s = shader::grass_mirror_signs({x, z}, 1u);
            REQUIRE(std::abs(s.x) == 1.0f);
            REQUIRE(std::abs(s.y) == 1.0f);
            ++counts[size_t((s.x < 0) + 2 * (s.y < 0))];
            same_as_right += s == shader::grass_mirror_signs({x + 1, z}, 1u);
            REQUIRE(s == shader::grass_mirror_signs({x, z}, 1u));
        }
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - 1024.0) * (c - 1024.0) / 1024.0;
    CHECK(chi2 < 16.3);  // 3 degrees of freedom, p = 0.001
    CHECK(std::abs(same_as_right - 1024) < 120);  // neighbours independent: 1/4 alike
    int differ = 0;
    for (int x = 0; x < 64; ++x) differ += shader::grass_mirror_signs({x, 0}, 1u) != shader::grass_mirror_signs({x, 0}, 2u);
    CHECK(differ > 32);
}

TEST_CASE("grass tiling: mirroring keeps a patch point in the patch, undoes itself, and only flips the signed axes") {
    for (glm::vec2 s : {glm::vec2(1, 1), glm::vec2(-1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)})
        for (glm::vec3 p : {glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0.2f, 0.0f, 0.9f), glm::vec3(1.0f, 2.0f, 0.5f)}) {
            const glm::vec3 m = shader::grass_mirror_patch_point(p, s);
            CHECK(m.y == p.y);
            CHECK(m.x == doctest::Approx(s.x > 0 ? p.x : 1.0f - p.x));
            CHECK(m.z == doctest::Approx(s.y > 0 ? p.z : 1.0f - p.z));
            CHECK(glm::length(shader::grass_mirror_patch_point(m, s) - p) < 1e-6f);  // up to rounding
        }
}

TEST_CASE("grass tiling: slice coordinates (eq 6.6) mirror exactly as geometry does (eq 6.7) inside a cell") {
    CHECK(shader::grass_fract(-0.25f) == 0.75f);  // not fmod's -0.25
    CHECK(shader::grass_fract(2.5f) == 0.5f);
    for (glm::vec2 s : {glm::vec2(1, 1), glm::vec2(-1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)})
        for (glm::vec2 u : {glm::vec2(3.25f, -1.5f), glm::vec2(0.125f, 7.875f), glm::vec2(-4.75f, 0.5f)}) {
            const glm::vec2 cell = glm::floor(u);
            const glm::vec2 local = u - cell;
            const glm::vec3 geometry = shader::grass_mirror_patch_point({local.x, 0.0f, local.y}, s);
            const glm::vec2 slice = shader::grass_mirror_slice_uv(u, s);
            CHECK(slice.x == doctest::Approx(cell.x + geometry.x));
            CHECK(slice.y == doctest::Approx(cell.y + geometry.z));
        }
    // The documented seam: with s = -1 a cell's lower edge maps to itself, geometry to the upper.
    CHECK(shader::grass_mirror_slice_uv({3.0f, 0.5f}, {-1.0f, 1.0f}).x == 3.0f);
}

TEST_CASE("grass field: a blade's root stays in its own cell, mirrored as the cell says") {
    GrassField field;
    field.cells = {8, 8};
    field.cell_size = 0.5f;
    field.origin = {-2.0f, 0.0f, -2.0f};
    BladePatchParams p;
    p.blades = 300;
    p.subdivisions = 0;
    const BladePatch patch = generate_blade_patch(p);
    for (int z = 0; z < 8; ++z)
        for (int x = 0; x < 8; ++x) {
            const glm::vec2 s = shader::grass_mirror_signs({x, z}, field.mirror_seed);
            for (const Blade& b : patch.blades) {
                const glm::vec3 w = field_point(field, {x, z}, b.root);
                const glm::vec3 local = (w - field.origin) / field.cell_size - glm::vec3(float(x), 0.0f, float(z));
                REQUIRE(local.x >= 0.0f);
                REQUIRE(local.x <= 1.0f);
                REQUIRE(local.z >= 0.0f);
                REQUIRE(local.z <= 1.0f);
                REQUIRE(local.x == doctest::Approx(s.x > 0 ? b.root.x : 1.0f - b.root.x).epsilon(1e-5));
                REQUIRE(local.z == doctest::Approx(s.y > 0 ? b.root.z : 1.0f - b.root.z).epsilon(1e-5));
            }
        }
}

TEST_CASE("grass field: density maps sample bilinearly between texel centres and clamp at the edges") {
    DensityMap empty;
    CHECK(empty.sample({0.3f, 0.7f}) == 1.0f);
    DensityMap m{2, 2, {0.0f, 1.0f, 0.5f, 0.25f}};  // row 0: 0, 1; row 1: 0.5, 0.25
    CHECK(m.sample({0.25f, 0.25f}) == doctest::Approx(0.0f));   // texel (0, 0)'s centre
    CHECK(m.sample({0.75f, 0.25f}) == doctest::Approx(1.0f));
    CHECK(m.sample({0.25f, 0.75f}) == doctest::Approx(0.5f));
    CHECK(m.sample({0.5f, 0.5f}) == doctest::Approx((0.0f + 1.0f + 0.5f + 0.25f) / 4.0f));
    CHECK(m.sample({0.0f, 0.0f}) == doctest::Approx(0.0f));     // clamped, not wrapped
    CHECK(m.sample({1.0f, 0.0f}) == doctest::Approx(1.0f));
    CHECK(m.sample({-5.0f, 9.0f}) == doctest::Approx(0.5f));
}

TEST_CASE("grass field: it draws the blades whose threshold the density reaches") {
    GrassField field;
    field.cells = {16, 16};
    BladePatchParams p;
    p.subdivisions = 0;
    const BladePatch patch = generate_blade_patch(p);
    const uint64_t all = uint64_t(16) * 16 * p.blades;
    CHECK(for_each_drawn_blade(field, patch) == all);  // no map: density 1
    field.density = {1, 1, {0.0f}};
    CHECK(for_each_drawn_blade(field, patch) == 0);  // thresholds in ]0, 1]
    field.density = {1, 1, {0.3f}};
    CHECK(double(for_each_drawn_blade(field, patch)) / double(all) == doctest::Approx(0.3).epsilon(0.05));
    // A ramp from 0 at x = 0 to 1 at the far side: half the blades, most where it is dense.
    field.density = {64, 1, {}};
    for (uint32_t i = 0; i < 64; ++i) field.density.values.push_back((float(i) + 0.5f) / 64.0f);
    uint64_t near_side = 0, far_side = 0;
    const uint64_t drawn = for_each_drawn_blade(field, patch, [&](const FieldBlade& b) {
        CHECK(patch.blades[b.blade].threshold <= b.density);
        (b.root.x < 8.0f ? near_side : far_side) += 1;
    });
    CHECK(double(drawn) / double(all) == doctest::Approx(0.5).epsilon(0.05));
    CHECK(double(far_side) / double(near_side) == doctest::Approx(3.0).epsilon(0.1));  // mean 3/4 against 1/4
}

TEST_CASE("grass field: a blade's density is its cell's corner values blended at its world root, whatever the mirror") {
    GrassField field;
    field.cells = {6, 5};
    field.cell_size = 0.7f;
    field.origin = {1.0f, 0.0f, -2.0f};
    field.mirror_seed = 9;
    field.density = {5, 3, {}};
    for (uint32_t i = 0; i < 15; ++i) field.density.values.push_back(float((i * 7) % 11) / 10.0f);
    BladePatchParams p;
    p.blades = 200;
    p.subdivisions = 0;
    const BladePatch patch = generate_blade_patch(p);
    int mirrored_both = 0, checked = 0;
    for_each_drawn_blade(field, patch, [&](const FieldBlade& b) {
        // Independently of the patch-order permutation: world corners, world position in the cell.
        const glm::vec4 world = cell_corner_densities(field, b.cell);
        const float fx = (b.root.x - field.origin.x) / field.cell_size - float(b.cell.x);
        const float fz = (b.root.z - field.origin.z) / field.cell_size - float(b.cell.y);
        const float near_edge = world.x + (world.y - world.x) * fx, far_edge = world.z + (world.w - world.z) * fx;
        CHECK(b.density == doctest::Approx(near_edge + (far_edge - near_edge) * fz).epsilon(1e-4));
        const glm::vec2 s = mirror_signs(field, b.cell);
        mirrored_both += s.x < 0.0f && s.y < 0.0f;
        ++checked;
    });
    CHECK(checked > 1000);
    CHECK(mirrored_both > 0);
    // The corners are the map's values at the cell's corners (bilinear between texel centres).
    const glm::vec4 c = cell_corner_densities(field, {2, 1});
    CHECK(c.x == doctest::Approx(field.density.sample({2.0f / 6.0f, 1.0f / 5.0f})));
    CHECK(c.w == doctest::Approx(field.density.sample({3.0f / 6.0f, 2.0f / 5.0f})));
}

TEST_CASE("grass density: the blend stays between its corners, clamps outside the patch, and 0 and 1 thin all or none") {
    using shader::grass_blade_drawn;
    using shader::grass_root_density;
    const glm::vec4 corners{0.0f, 1.0f, 0.25f, 0.5f};
    for (float x : {-1e30f, -1.0f, 0.0f, 0.3f, 1.0f, 7.0f, 1e30f})
        for (float z : {-1e30f, 0.0f, 0.5f, 1.0f, 1e30f}) {
            const float d = grass_root_density(corners, {x, z});
            CHECK(std::isfinite(d));
            CHECK(d >= 0.0f);
            CHECK(d <= 1.0f);
        }
    CHECK(grass_root_density(corners, {0.0f, 0.0f}) == 0.0f);
    CHECK(grass_root_density(corners, {1.0f, 0.0f}) == 1.0f);
    CHECK(grass_root_density(corners, {0.0f, 1.0f}) == 0.25f);
    CHECK(grass_root_density(corners, {1.0f, 1.0f}) == 0.5f);
    CHECK(grass_root_density(corners, {-3.0f, 5.0f}) == 0.25f);  // clamped to the patch's corner
    CHECK(grass_root_density(corners, {0.5f, 0.5f}) == doctest::Approx(0.4375f));
    // Thresholds lie in ]0, 1]: density 0 draws none, 1 draws all, at the ends of the range too.
    for (float t : {1.0f / 16777216.0f, 0.5f, 1.0f}) {
        CHECK_FALSE(grass_blade_drawn(t, 0.0f));
        CHECK(grass_blade_drawn(t, 1.0f));
    }
    // Each mirror permutes the corners so that patch point (0, 0) reads the world corner it lands on.
    const glm::vec4 world{1.0f, 2.0f, 3.0f, 4.0f};
    CHECK(shader::grass_patch_corner_densities(world, {1.0f, 1.0f}) == world);
    CHECK(shader::grass_patch_corner_densities(world, {-1.0f, 1.0f}) == glm::vec4(2.0f, 1.0f, 4.0f, 3.0f));
    CHECK(shader::grass_patch_corner_densities(world, {1.0f, -1.0f}) == glm::vec4(3.0f, 4.0f, 1.0f, 2.0f));
    CHECK(shader::grass_patch_corner_densities(world, {-1.0f, -1.0f}) == glm::vec4(4.0f, 3.0f, 2.0f, 1.0f));
}

TEST_CASE("grass density maps: uniform, a ramp along x and seeded clearings, in [low, high]") {
    const DensityMap uniform = density_map(DensityPattern::uniform, 0.2f, 0.7f, 16, 4, 1);
    CHECK(uniform.sample({0.3f, 0.9f}) == 0.7f);
    // The ramp: low at the first column, high at the last, linear in between (bilinear sampling
    // of a linear ramp is exact between the texel centres).
    const DensityMap ramp = density_map(DensityPattern::ramp_x, 0.2f, 0.8f, 33, 4, 1);
    CHECK(ramp.sample({0.0f, 0.5f}) == doctest::Approx(0.2f));
    CHECK(ramp.sample({1.0f, 0.1f}) == doctest::Approx(0.8f));
    const float c = (16.0f + 0.5f) / 33.0f;
    CHECK(ramp.sample({c, 0.7f}) == doctest::Approx(0.5f));
    // Clearings: both ends present, about half the field low, the rest high, a smooth edge;
    // fixed by the seed.
    const DensityMap clearings = density_map(DensityPattern::clearings, 0.0f, 1.0f, 64, 4, 3);
    int low = 0, high = 0, edge = 0;
    for (float v : clearings.values) {
        REQUIRE(v >= 0.0f);
        REQUIRE(v <= 1.0f);
        low += v == 0.0f;
        high += v == 1.0f;
        edge += v > 0.0f && v < 1.0f;
    }
    const int n = int(clearings.values.size());
    CAPTURE(low);
    CAPTURE(high);
    CAPTURE(edge);
    CHECK(low > n / 4);
    CHECK(high > n / 4);
    CHECK(edge > 0);
    CHECK(edge < n / 4);
    CHECK(density_map(DensityPattern::clearings, 0.0f, 1.0f, 64, 4, 3).values == clearings.values);
    CHECK(density_map(DensityPattern::clearings, 0.0f, 1.0f, 64, 4, 4).values != clearings.values);
    CHECK_THROWS_AS(density_map(DensityPattern::ramp_x, 0.0f, 1.0f, 0, 4, 1), std::invalid_argument);
}

TEST_CASE("grass density maps: a field with clearings draws the blades its cells' corners keep, none in a clearing") {
    GrassField field;
    field.cells = {8, 8};
    field.density = density_map(DensityPattern::clearings, 0.0f, 1.0f, 64, 2, 5);
    BladePatchParams params;
    params.blades = 200;
    const BladePatch patch = generate_blade_patch(params);
    int empty_cells = 0, full_cells = 0;
    for (int z = 0; z < 8; ++z)
        for (int x = 0; x < 8; ++x) {
            const glm::vec4 corners = cell_corner_densities(field, {x, z});
            empty_cells += corners == glm::vec4(0.0f);
            full_cells += corners == glm::vec4(1.0f);
        }
    CHECK(empty_cells > 0);
    CHECK(full_cells > 0);
    std::array<int, 64> drawn{};
    const uint64_t total = for_each_drawn_blade(field, patch, [&](const FieldBlade& b) { ++drawn[size_t(b.cell.y) * 8 + size_t(b.cell.x)]; });
    CHECK(total > 0);
    CHECK(total < 64ull * 200);
    for (int z = 0; z < 8; ++z)
        for (int x = 0; x < 8; ++x) {
            const glm::vec4 corners = cell_corner_densities(field, {x, z});
            if (corners == glm::vec4(0.0f)) CHECK(drawn[size_t(z) * 8 + size_t(x)] == 0);
            if (corners == glm::vec4(1.0f)) CHECK(drawn[size_t(z) * 8 + size_t(x)] == 200);
        }
}
