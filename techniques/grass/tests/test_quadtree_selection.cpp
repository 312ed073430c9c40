// Lemme's quadtree traversal (common/quadtree_selection.hpp) against a brute-force pass over every
// cell, written apart from it: for each band, every cell that can be seen and whose centre lies
// inside the band's distances is drawn exactly once, as a cell or inside a macro-cell; no cell is
// drawn twice; a macro-cell lies wholly within its band and is an aligned square no wider than the
// band allows; a cell out of view is never drawn alone; and the tree visits far fewer nodes than
// the field has cells. A traversal without its frustum test, or one that draws a node before it
// lies wholly within a band, fails here.
#include "../common/macro_cells.hpp"
#include "../common/quadtree_selection.hpp"
#include "../shaders/lod_selection.h"

#include "scene/camera.hpp"
#include "support/cpu_checks.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace canopy;
using namespace canopy::grass;

namespace {

constexpr uint32_t kWidth = 320, kHeight = 180;

// A 150 x 97 field of 1 m cells (neither side a power of two), blades up to 0.35 m leaning 0.05 m
// out of their cell.
QuadtreeField test_field() {
    QuadtreeField f;
    f.cells = {150, 97};
    f.origin = glm::vec3(-75.0f, 0.0f, -48.5f);
    f.cell_size = 1.0f;
    f.patch_box = Bounds{glm::vec3(-0.05f, 0.0f, -0.03f), glm::vec3(1.04f, 0.35f, 1.05f)};
    return f;
}

// grass.lod's three bands at its defaults, with Lemme's largest macro-cells (40 and 500 cells).
std::vector<QuadtreeBand> lod_bands() {
    std::vector<QuadtreeBand> bands;
    const int representations[3] = {shader::GRASS_LOD_GEOMETRY, shader::GRASS_LOD_VOLUME, shader::GRASS_LOD_IMAGE};
    const uint32_t macros[3] = {1, 40, 500};
    for (int b = 0; b < 3; ++b) {
        const glm::vec2 d = shader::lod_band_distances(representations[b], 5.0f, 20.0f, 50.0f, 80.0f);
        bands.push_back({d.x, d.y, macros[b]});
    }
    return bands;
}

Camera camera(glm::vec3 position, glm::vec3 target, float fov = 45.0f) {
    Camera c;
    c.position = position;
    c.target = target;
    c.fov_y_degrees = fov;
    c.near_plane = 0.05f;
    c.far_plane = 1000.0f;
    return c;
}

// Whether a cell's box (its patch mirrored either way) may be in view (support/cpu_checks, written
// from the clip-space definition, not with the shaders' header).
// `grid`: the field's grid heights on a terrain (empty: flat); a cell's box then spans its four
// corners' heights, and its centre stands at its first corner's.
float grid_at(const QuadtreeField& f, const std::vector<float>& grid, uint32_t x, uint32_t z) {
    return grid.empty() ? 0.0f : grid[size_t(z) * (f.cells.x + 1) + x];
}

bool cell_in_view(const QuadtreeField& f, glm::uvec2 cell, const glm::mat4& view_proj,
                  const std::vector<float>& grid = {}) {
    float low = 1e30f, high = -1e30f;
    for (uint32_t c = 0; c < 4; ++c) {
        const float h = grid_at(f, grid, cell.x + (c & 1), cell.y + (c >> 1));
        low = std::min(low, h);
        high = std::max(high, h);
    }
    const Bounds& b = f.patch_box;
    const float lo_x = std::min(b.min.x, 1.0f - b.max.x), hi_x = std::max(b.max.x, 1.0f - b.min.x);
    const float lo_z = std::min(b.min.z, 1.0f - b.max.z), hi_z = std::max(b.max.z, 1.0f - b.min.z);
    std::array<glm::vec3, 8> corners;
    for (int c = 0; c < 8; ++c)
        corners[size_t(c)] = f.origin + f.cell_size * glm::vec3(float(cell.x) + ((c & 1) ? hi_x : lo_x),
                                                                (c & 2) ? b.max.y + high / f.cell_size
                                                                        : b.min.y + low / f.cell_size,
                                                                float(cell.y) + ((c & 4) ? hi_z : lo_z));
    return grass::test::corners_may_be_seen(view_proj, corners);
}

float centre_distance(const QuadtreeField& f, glm::uvec2 cell, glm::vec3 eye, const std::vector<float>& grid = {}) {
    const glm::vec3 centre = f.origin + f.cell_size * glm::vec3(float(cell.x) + 0.5f, 0.0f, float(cell.y) + 0.5f) +
                             glm::vec3(0.0f, grid_at(f, grid, cell.x, cell.y), 0.0f);
    return glm::length(centre - eye);
}

bool within(float d, const QuadtreeBand& band, float tolerance) {
    const bool unbounded = band.max_distance >= shader::LOD_NO_DISTANCE;
    return d >= band.min_distance - tolerance && (unbounded || d <= band.max_distance + tolerance);
}

uint32_t ceil_pow2(uint32_t n) {
    uint32_t p = 1;
    while (p < n) p *= 2;
    return p;
}

// Grid heights of hills up to 12 m over the field, waves of about 40 and 28 m.
std::vector<float> hills_grid(const QuadtreeField& f) {
    std::vector<float> grid(size_t(f.cells.x + 1) * (f.cells.y + 1));
    for (uint32_t z = 0; z <= f.cells.y; ++z)
        for (uint32_t x = 0; x <= f.cells.x; ++x)
            grid[size_t(z) * (f.cells.x + 1) + x] = 6.0f + 6.0f * std::sin(float(x) / 6.5f) * std::cos(float(z) / 4.5f);
    return grid;
}

// Every check of the file's header for one camera; the selection, for further checks.
QuadtreeSelection check_selection(const QuadtreeField& f, const std::vector<QuadtreeBand>& bands, const Camera& cam,
                                  const std::vector<float>& grid = {}) {
    const glm::mat4 view_proj = view_projection(cam, kWidth, kHeight);
    const QuadtreeSelection s = select_cells(f, bands, cam.position, view_proj, grid);
    REQUIRE(s.bands.size() == bands.size());
    for (size_t b = 0; b < bands.size(); ++b) {
        CAPTURE(b);
        const QuadtreeBand& band = bands[b];
        std::vector<int> drawn(size_t(f.cells.x) * f.cells.y, 0);
        int misplaced = 0, too_wide = 0, unaligned = 0, outside_band = 0, hidden_cells = 0;
        for (const QuadtreeNode& node : s.bands[b]) {
            const uint32_t size = ceil_pow2(std::max(node.span.x, node.span.y));
            if (node.first.x % size || node.first.y % size) ++unaligned;
            if (node.first.x + node.span.x > f.cells.x || node.first.y + node.span.y > f.cells.y) ++misplaced;
            if (node.cells() > 1 && std::max(node.span.x, node.span.y) > band.max_macro) ++too_wide;
            for (uint32_t z = node.first.y; z < node.first.y + node.span.y; ++z)
                for (uint32_t x = node.first.x; x < node.first.x + node.span.x; ++x) {
                    if (x >= f.cells.x || z >= f.cells.y) continue;
                    ++drawn[size_t(z) * f.cells.x + x];
                    const float d = centre_distance(f, {x, z}, cam.position, grid);
                    // A macro-cell lies wholly within the band; a single cell at least touches it.
                    if (!within(d, band, node.cells() > 1 ? 1e-3f : 0.05f)) ++outside_band;
                    if (node.cells() == 1 && !cell_in_view(f, {x, z}, view_proj, grid)) ++hidden_cells;
                }
        }
        // On a terrain: each node carries its ground's range, and a band's macro-cells are flat enough.
        int wrong_heights = 0, uneven = 0;
        for (const QuadtreeNode& node : s.bands[b]) {
            const MacroInstance m(node.first.x, node.first.y, node.span.x, node.span.y);
            const glm::vec2 range = grid.empty() ? glm::vec2(0.0f) : macro_height_range(grid, f.cells, m);
            wrong_heights += node.heights != range;
            if (!grid.empty() && node.cells() > 1) uneven += macro_unplanarity(grid, f.cells, m) > band.max_unplanarity;
        }
        CHECK(wrong_heights == 0);
        CHECK(uneven == 0);
        CHECK(misplaced == 0);
        CHECK(too_wide == 0);
        CHECK(unaligned == 0);
        CHECK(outside_band == 0);
        CHECK(hidden_cells == 0);
        int twice = 0, missing = 0;
        for (uint32_t z = 0; z < f.cells.y; ++z)
            for (uint32_t x = 0; x < f.cells.x; ++x) {
                const int n = drawn[size_t(z) * f.cells.x + x];
                twice += n > 1;
                const float d = centre_distance(f, {x, z}, cam.position, grid);
                const bool surely_in_band = d > band.min_distance + 0.01f &&
                                            (band.max_distance >= shader::LOD_NO_DISTANCE || d < band.max_distance - 0.01f);
                if (surely_in_band && cell_in_view(f, {x, z}, view_proj, grid) && n == 0) ++missing;
            }
        CHECK(twice == 0);
        CHECK(missing == 0);
    }
    return s;
}

}  // namespace

TEST_CASE("quadtree: the root level covers the field") {
    CHECK(quadtree_root_level({1, 1}) == 0);
    CHECK(quadtree_root_level({32, 32}) == 5);
    CHECK(quadtree_root_level({33, 1}) == 6);
    CHECK(quadtree_root_level({380, 532}) == 10);  // Lemme's football field
}

TEST_CASE("quadtree: a node's centre distances bound those of its cells") {
    const QuadtreeField f = test_field();
    for (const glm::vec3 eye : {glm::vec3(3.3f, 1.7f, -2.1f), glm::vec3(-200.0f, 40.0f, 10.0f), glm::vec3(0.0f)}) {
        for (const QuadtreeNode node : {QuadtreeNode{{0, 0}, {1, 1}}, QuadtreeNode{{64, 32}, {32, 32}},
                                        QuadtreeNode{{128, 64}, {22, 33}}}) {
            float lo = 1e30f, hi = 0.0f;
            for (uint32_t z = node.first.y; z < node.first.y + node.span.y; ++z)
                for (uint32_t x = node.first.x; x < node.first.x + node.span.x; ++x) {
                    const float d = centre_distance(f, {x, z}, eye);
                    lo = std::min(lo, d);
                    hi = std::max(hi, d);
                }
            const glm::vec2 d = node_centre_distances(f, node, eye);
            CHECK(d.x <= lo + 1e-4f);
            CHECK(d.y == doctest::Approx(hi).epsilon(1e-5));  // the farthest centre is a corner's
            CHECK(d.x >= lo - 0.75f);                          // within the node's gaps between centres
        }
    }
}

TEST_CASE("quadtree: every cell in view is drawn once per band it lies in, macro-cells wholly inside their band") {
    const QuadtreeField f = test_field();
    const std::vector<QuadtreeBand> bands = lod_bands();
    SUBCASE("player height, looking along the field") {
        const QuadtreeSelection s = check_selection(f, bands, camera({-60.0f, 1.8f, 0.0f}, {0.0f, 0.5f, 0.0f}));
        CHECK(!s.bands[0].empty());
        CHECK(!s.bands[1].empty());
        CHECK(!s.bands[2].empty());
    }
    SUBCASE("an ant's view, 5 cm above the ground") {
        check_selection(f, bands, camera({10.0f, 0.05f, 3.0f}, {40.0f, 0.05f, 10.0f}));
    }
    SUBCASE("high above, the whole field in view") {
        const QuadtreeSelection s = check_selection(f, bands, camera({0.0f, 150.0f, 120.0f}, {0.0f, 0.0f, 0.0f}));
        CHECK(s.bands[0].empty());  // every cell farther than the blades reach
        // Far from the bands' edges, cells gather into macro-cells: far fewer draws than cells.
        size_t far_cells = 0;
        for (const QuadtreeNode& n : s.bands[2]) far_cells += n.cells();
        CHECK(far_cells > 10000);
        CHECK(s.bands[2].size() * 20 < far_cells);
        CHECK(s.nodes_visited * 10 < size_t(f.cells.x) * f.cells.y);
    }
    SUBCASE("looking away from the field: nothing") {
        const QuadtreeSelection s = check_selection(f, bands, camera({0.0f, 2.0f, 60.0f}, {0.0f, 2.0f, 100.0f}));
        for (const auto& band : s.bands) CHECK(band.empty());
    }
    SUBCASE("single cells only (largest macro-cell 1)") {
        std::vector<QuadtreeBand> cells_only = bands;
        for (QuadtreeBand& b : cells_only) b.max_macro = 1;
        const QuadtreeSelection s = check_selection(f, cells_only, camera({-30.0f, 6.0f, 10.0f}, {10.0f, 0.0f, 0.0f}));
        for (const auto& band : s.bands)
            for (const QuadtreeNode& n : band) CHECK(n.cells() == 1);
    }
}

TEST_CASE("quadtree: macro-cells grow with the distance from the band's edges (Lemme Fig 6.5)") {
    const QuadtreeField f = test_field();
    const std::vector<QuadtreeBand> bands = lod_bands();
    const Camera cam = camera({-74.0f, 3.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    const QuadtreeSelection s = select_cells(f, bands, cam.position, view_projection(cam, kWidth, kHeight));
    // A single cell is drawn only where its parent straddled the band's edge: within a parent's
    // diagonal of image_start. Farther out, the nodes are wider on average.
    float single_past = 0.0f;
    double near_width = 0, near_count = 0, far_width = 0, far_count = 0;
    uint32_t widest = 0;
    for (const QuadtreeNode& n : s.bands[2]) {
        const float past = node_centre_distances(f, n, cam.position).x - bands[2].min_distance;
        if (n.cells() == 1) single_past = std::max(single_past, past);
        widest = std::max(widest, n.span.x);
        (past < 10.0f ? near_width : far_width) += n.span.x;
        (past < 10.0f ? near_count : far_count) += 1;
    }
    CAPTURE(single_past);
    CHECK(single_past < 2.0f * std::sqrt(2.0f) * f.cell_size);
    CHECK(widest >= 32);
    REQUIRE(near_count > 0);
    REQUIRE(far_count > 0);
    CHECK(near_width / near_count * 4 < far_width / far_count);
}

TEST_CASE("quadtree on a terrain: boxes and centres rise with the ground, and the far band's macro-cells are flat enough") {
    const QuadtreeField f = test_field();
    const std::vector<float> grid = hills_grid(f);
    std::vector<QuadtreeBand> bands = lod_bands();
    bands[2].max_unplanarity = 0.05f;
    SUBCASE("looking up a slope from a valley: flat boxes would lie below the view") {
        const QuadtreeSelection s = check_selection(f, bands, camera({-40.0f, 3.0f, 0.0f}, {0.0f, 14.0f, 0.0f}), grid);
        CHECK(!s.bands[0].empty());
        CHECK(!s.bands[2].empty());
    }
    SUBCASE("player height over the hills") {
        check_selection(f, bands, camera({-60.0f, 9.0f, 5.0f}, {0.0f, 6.0f, 0.0f}), grid);
    }
    SUBCASE("high above: the far band's macro-cells split where the ground is uneven, never above the threshold") {
        const QuadtreeSelection uneven = check_selection(f, bands, camera({0.0f, 150.0f, 120.0f}, {0.0f, 0.0f, 0.0f}), grid);
        bands[2].max_unplanarity = std::numeric_limits<float>::infinity();
        const QuadtreeSelection any = check_selection(f, bands, camera({0.0f, 150.0f, 120.0f}, {0.0f, 0.0f, 0.0f}), grid);
        CHECK(uneven.bands[2].size() > any.bands[2].size() * 2);
    }
}

TEST_CASE("quadtree: Lemme's hilltop band keeps the far band's cells whose box reaches above the eye (§6.4.6)") {
    const QuadtreeField f = test_field();
    const std::vector<float> grid = hills_grid(f);
    std::vector<QuadtreeBand> bands = lod_bands();
    QuadtreeBand hilltop = bands[2];
    hilltop.max_macro = 40;
    hilltop.above_eye = true;
    bands.push_back(hilltop);
    // The top of a box: its highest grid height plus the tallest blade (field units times the cell).
    const auto cell_top = [&](uint32_t x, uint32_t z) {
        float high = -1e30f;
        for (uint32_t c = 0; c < 4; ++c) high = std::max(high, grid_at(f, grid, x + (c & 1), z + (c >> 1)));
        return f.origin.y + high + f.cell_size * f.patch_box.max.y;
    };
    const auto drawn_cells = [&](const std::vector<QuadtreeNode>& nodes) {
        std::vector<int> drawn(size_t(f.cells.x) * f.cells.y, 0);
        for (const QuadtreeNode& n : nodes)
            for (uint32_t z = n.first.y; z < n.first.y + n.span.y; ++z)
                for (uint32_t x = n.first.x; x < n.first.x + n.span.x; ++x) ++drawn[size_t(z) * f.cells.x + x];
        return drawn;
    };
    SUBCASE("from 10 m up, on the hills (up to 12 m): the far band's crests, and only cells whose box reaches above the eye") {
        const Camera cam = camera({-70.0f, 10.0f, 2.0f}, {0.0f, 6.0f, 0.0f}, 60.0f);
        const QuadtreeSelection s = check_selection(f, {bands.begin(), bands.begin() + 3}, cam, grid);
        const QuadtreeSelection h = select_cells(f, bands, cam.position, view_projection(cam, kWidth, kHeight), grid);
        REQUIRE(h.bands.size() == 4);
        // The other bands are as without the hilltops.
        for (size_t b = 0; b < 3; ++b) CHECK(h.bands[b].size() == s.bands[b].size());
        const std::vector<int> far = drawn_cells(h.bands[2]), top = drawn_cells(h.bands[3]);
        std::vector<QuadtreeBand> single = bands;
        single[3].max_macro = 1;
        const glm::mat4 view_proj = view_projection(cam, kWidth, kHeight);
        const std::vector<int> h1 = drawn_cells(select_cells(f, single, cam.position, view_proj, grid).bands[3]);
        int extra = 0, missing_single = 0, single_cells = 0;
        for (int n : h1) single_cells += n > 0;
        int low_nodes = 0, too_wide = 0, not_far = 0, twice = 0, missing = 0, far_cells = 0, top_cells = 0;
        for (const QuadtreeNode& n : h.bands[3]) {
            low_nodes += f.origin.y + n.heights.y + f.cell_size * f.patch_box.max.y <= cam.position.y;
            too_wide += std::max(n.span.x, n.span.y) > hilltop.max_macro;
        }
        for (uint32_t z = 0; z < f.cells.y; ++z)
            for (uint32_t x = 0; x < f.cells.x; ++x) {
                const size_t i = size_t(z) * f.cells.x + x;
                far_cells += far[i] > 0;
                top_cells += top[i] > 0;
                not_far += top[i] > 0 && far[i] == 0;
                twice += top[i] > 1;
                // A far cell whose own box reaches above the eye is a hilltop's.
                missing += far[i] > 0 && cell_top(x, z) > cam.position.y + 1e-3f && top[i] == 0;
                // In single cells, only those (within the slack of a rounding), each if in view
                // (a far macro-cell may hold cells out of view).
                extra += h1[i] > 0 && cell_top(x, z) <= cam.position.y - 1e-3f;
                missing_single += far[i] > 0 && cell_top(x, z) > cam.position.y + 1e-3f && h1[i] == 0 &&
                                  cell_in_view(f, {x, z}, view_proj, grid);
            }
        CAPTURE(far_cells);
        CAPTURE(top_cells);
        CHECK(low_nodes == 0);
        CHECK(too_wide == 0);
        CHECK(not_far == 0);
        CHECK(twice == 0);
        CHECK(missing == 0);
        CHECK(top_cells > 100);
        CHECK(top_cells < far_cells);  // the valleys' far cells lie below the eye
        CAPTURE(single_cells);
        CHECK(extra == 0);
        CHECK(missing_single == 0);
        CHECK(single_cells * 2 < far_cells);  // in single cells, the crests alone
    }
    SUBCASE("from 150 m up nothing reaches above the eye") {
        const Camera cam = camera({0.0f, 150.0f, 120.0f}, {0.0f, 0.0f, 0.0f});
        const QuadtreeSelection h = select_cells(f, bands, cam.position, view_projection(cam, kWidth, kHeight), grid);
        CHECK(!h.bands[2].empty());
        CHECK(h.bands[3].empty());
    }
}
