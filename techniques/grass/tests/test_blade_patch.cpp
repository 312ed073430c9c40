// The blade patch generator (common/blade_patch.hpp): Lemme's tessellation counts, the spine of
// eq 4.1-4.2, roots, widths, normals, determinism, and its extremes.
#include "../common/blade_patch.hpp"
#include "../shaders/blade_curve.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <stdexcept>

using namespace canopy::grass;
namespace shader = canopy::shader;

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Every structural property of a generated patch, at any parameters.
void check_patch(const BladePatch& patch) {
    const BladePatchParams& p = patch.params;
    const uint32_t per_blade = vertices_per_blade(p.subdivisions);
    const uint32_t segments = segments_per_blade(p.subdivisions);
    REQUIRE(patch.blades.size() == p.blades);
    REQUIRE(patch.vertices.size() == size_t(p.blades) * per_blade);
    REQUIRE(patch.indices.size() == size_t(p.blades) * 3 * triangles_per_blade(p.subdivisions));
    for (size_t k = 0; k < patch.indices.size(); ++k) {
        const size_t blade = k / (6 * segments);
        const uint32_t index = patch.indices[k];
        REQUIRE(index >= blade * per_blade);  // a triangle joins vertices of its own blade only
        REQUIRE(index < (blade + 1) * per_blade);
    }
    for (uint32_t i = 0; i < p.blades; ++i) {
        const Blade& b = patch.blades[i];
        CAPTURE(i);
        REQUIRE(b.root.x >= 0.0f);
        REQUIRE(b.root.x < 1.0f);
        REQUIRE(b.root.z >= 0.0f);
        REQUIRE(b.root.z < 1.0f);
        REQUIRE(b.root.y == 0.0f);
        REQUIRE(b.threshold > 0.0f);
        REQUIRE(b.threshold <= 1.0f);
        REQUIRE(b.width >= p.width_min);
        REQUIRE(b.width <= p.width_max);
        REQUIRE(b.colour >= 1.0f - p.blade_colour_variation);
        REQUIRE(b.colour <= 1.0f);
        const float tip = shader::blade_point(b.launch, b.gravity, 1.0f).y;
        REQUIRE(tip >= p.height_min * (1.0f - 1e-5f));
        REQUIRE(tip <= p.height_max * (1.0f + 1e-5f));
        float previous_height = -1.0f, previous_length = INFINITY;
        for (uint32_t s = 0; s <= segments; ++s) {
            const BladeVertex& left = patch.vertices[size_t(i) * per_blade + 2 * s];
            const BladeVertex& right = patch.vertices[size_t(i) * per_blade + 2 * s + 1];
            REQUIRE(finite(left.position));
            REQUIRE(finite(left.normal));
            REQUIRE(left.uv == glm::vec2(0.0f, float(s) / float(segments)));
            REQUIRE(right.uv == glm::vec2(1.0f, float(s) / float(segments)));
            REQUIRE(glm::length(right.position - left.position) == doctest::Approx(b.width).epsilon(1e-4));
            const glm::vec3 spine = 0.5f * (left.position + right.position);
            // The spine is eq 4.1 from the root at t = s / segments.
            const glm::vec3 expected = b.root + b.launch * (float(s) / float(segments)) +
                                       b.gravity * (float(s) / float(segments)) * (float(s) / float(segments));
            REQUIRE(glm::length(spine - expected) < 1e-5f);
            // Rising all the way to the tip; segments no longer towards the tip (Lemme L321).
            REQUIRE(spine.y >= previous_height - 1e-6f);
            previous_height = spine.y;
            if (s > 0) {
                const BladeVertex& below = patch.vertices[size_t(i) * per_blade + 2 * (s - 1)];
                const float length = glm::length(left.position - below.position);
                REQUIRE(length <= previous_length * (1.0f + 1e-4f));
                previous_length = length;
            }
            const glm::vec3 tangent = shader::blade_tangent(b.launch, b.gravity, float(s) / float(segments));
            REQUIRE(glm::length(left.normal) == doctest::Approx(1.0f).epsilon(1e-5));
            REQUIRE(std::abs(glm::dot(left.normal, glm::normalize(tangent))) < 1e-5f);
            REQUIRE(std::abs(glm::dot(left.normal, b.across)) < 1e-5f);
            REQUIRE(left.root == b.root);
            REQUIRE(left.threshold == b.threshold);
            REQUIRE(left.colour <= b.colour);
            REQUIRE(left.colour >= b.colour * (1.0f - p.vertex_colour_variation) - 1e-6f);
            REQUIRE(patch.tallest >= spine.y);
        }
    }
}

bool same_bytes(const BladePatch& a, const BladePatch& b, size_t blades) {
    const size_t n = blades * vertices_per_blade(a.params.subdivisions);
    return std::memcmp(a.vertices.data(), b.vertices.data(), n * sizeof(BladeVertex)) == 0;
}

}  // namespace

TEST_CASE("grass blades: Lemme's '4 subdivisions' are 10 triangles, which gives Table 7.1's 24.6 M") {
    CHECK(triangles_per_blade(4) == 10);
    CHECK(vertices_per_blade(4) == 12);
    // L1026 and L1035: 2400 blades a patch, 1024 patches, "24.6 mio." triangles.
    CHECK(uint64_t(2400) * triangles_per_blade(4) * 1024 == 24'576'000);
    // Fig 3.1 (L229): 30 triangles a blade.
    CHECK(triangles_per_blade(14) == 30);
    const BladePatch patch = generate_blade_patch({});
    CHECK(patch.indices.size() / 3 == 24'000);  // "24 thousand triangles" a patch (L1026)
    check_patch(patch);
}

TEST_CASE("grass blades: every property holds at the defaults, for both root placements and both threshold kinds") {
    for (RootPlacement roots : {RootPlacement::uniform, RootPlacement::stratified})
        for (ThresholdDistribution kind : {ThresholdDistribution::uniform, ThresholdDistribution::clustered}) {
            BladePatchParams p;
            p.roots = roots;
            p.thresholds.distribution = kind;
            CAPTURE(int(roots));
            CAPTURE(int(kind));
            check_patch(generate_blade_patch(p));
        }
}

TEST_CASE("grass blades: extremes stay finite and keep every property") {
    BladePatchParams p;
    p.blades = 257;
    SUBCASE("one segment") { p.subdivisions = 0; }
    SUBCASE("64 subdivisions") { p.subdivisions = 64; }
    SUBCASE("steepest tilt, full bend") {
        p.tilt_min_degrees = p.tilt_max_degrees = 80.0f;
        p.bend_min = p.bend_max = 1.0f;
    }
    SUBCASE("vertical and straight") {
        p.tilt_min_degrees = p.tilt_max_degrees = 0.0f;
        p.bend_min = p.bend_max = 0.0f;
    }
    SUBCASE("tiny and tall") {
        p.height_min = 1e-4f;
        p.height_max = 10.0f;
        p.width_min = p.width_max = 1e-5f;
    }
    SUBCASE("no colour variation, full variation") {
        p.blade_colour_variation = 0.0f;
        p.vertex_colour_variation = 1.0f;
    }
    SUBCASE("one blade, stratified") {
        p.blades = 1;
        p.roots = RootPlacement::stratified;
    }
    check_patch(generate_blade_patch(p));
}

TEST_CASE("grass blades: full bend puts the tip exactly at the top of the parabola") {
    BladePatchParams p;
    p.blades = 64;
    p.bend_min = p.bend_max = 1.0f;
    for (const Blade& b : generate_blade_patch(p).blades)
        CHECK(shader::blade_tangent(b.launch, b.gravity, 1.0f).y == doctest::Approx(0.0f).scale(1.0f).epsilon(1e-5));
    // The pull that does it is half the rise, and a straight blade has none.
    CHECK(shader::blade_max_pull(0.3f) == doctest::Approx(0.15f));
}

TEST_CASE("grass blades: stratified roots put exactly one blade in each grid cell") {
    CHECK(stratified_grid(2400) == glm::uvec2(48, 50));
    CHECK(stratified_grid(2399) == glm::uvec2(1, 2399));  // prime: strips
    CHECK(stratified_grid(1) == glm::uvec2(1, 1));
    BladePatchParams p;
    p.roots = RootPlacement::stratified;
    const BladePatch patch = generate_blade_patch(p);
    std::set<std::pair<int, int>> cells;
    for (const Blade& b : patch.blades) cells.insert({int(b.root.x * 48.0f), int(b.root.z * 50.0f)});
    CHECK(cells.size() == 2400);
}

TEST_CASE("grass blades: deterministic in the seed, and blade i does not depend on the count") {
    BladePatchParams p;
    const BladePatch a = generate_blade_patch(p), b = generate_blade_patch(p);
    CHECK(same_bytes(a, b, p.blades));
    BladePatchParams fewer = p;
    fewer.blades = 100;
    CHECK(same_bytes(a, generate_blade_patch(fewer), 100));
    BladePatchParams other = p;
    other.seed = 2;
    CHECK_FALSE(same_bytes(a, generate_blade_patch(other), 1));
}

TEST_CASE("grass blades: uniform roots cover the patch evenly") {
    BladePatchParams p;
    p.blades = 40000;
    p.subdivisions = 0;
    const BladePatch patch = generate_blade_patch(p);
    std::array<int, 16> counts{};
    for (const Blade& b : patch.blades) ++counts[size_t(int(b.root.x * 4.0f) * 4 + int(b.root.z * 4.0f))];
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - 2500.0) * (c - 2500.0) / 2500.0;
    CHECK(chi2 < 37.7);  // 15 degrees of freedom, p = 0.001
    // The azimuths are uniform too: as many blades lean east as west.
    int east = 0;
    for (const Blade& b : patch.blades) east += b.launch.x > 0.0f;
    CHECK(std::abs(east - 20000) < 600);
}

TEST_CASE("grass blades: parameters out of range are refused by name") {
    const auto refused = [](const char* name, auto change) {
        CAPTURE(name);
        BladePatchParams p;
        change(p);
        try {
            generate_blade_patch(p);
            FAIL("accepted");
        } catch (const std::invalid_argument& e) {
            CHECK(std::string(e.what()).find(name) != std::string::npos);
        }
    };
    refused("blades", [](BladePatchParams& p) { p.blades = 0; });
    refused("subdivisions", [](BladePatchParams& p) { p.subdivisions = 65; });
    refused("height", [](BladePatchParams& p) { p.height_min = 0.5f; });  // above height_max
    refused("tilt", [](BladePatchParams& p) { p.tilt_max_degrees = 89.0f; });
    refused("bend", [](BladePatchParams& p) { p.bend_max = 1.5f; });
    refused("width", [](BladePatchParams& p) { p.width_min = std::nanf(""); });
    refused("noise_periods", [](BladePatchParams& p) {
        p.thresholds.distribution = ThresholdDistribution::clustered;
        p.thresholds.noise_periods = 0;
    });
}
