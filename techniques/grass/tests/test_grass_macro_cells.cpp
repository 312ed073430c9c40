// Macro-cells (Lemme §6.2) for grass.image and grass.volume: the macro-cells tile the field, each
// cell once, cut at its far edges; the shared functions find a point's cell, its mirrored patch
// point and the slice a mirrored cell shows; a field drawn with macro-cells of any size is the
// same image as with one macro-cell per cell; and seen from afar, the mirrored cells cover what
// the reference's rays hit (and a field mirrored by another seed does not). A macro-cell that
// reads its first cell for all of its cells, ignores a cell's mirror or walks n planes instead of
// n k fails a check here.
#include "support/bake_truth.hpp"

#include "../common/grass_field.hpp"
#include "../common/grass_population.hpp"
#include "../common/macro_cells.hpp"
#include "../shaders/cell_mirroring.h"
#include "../shaders/grass_macro_cells.h"

#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "scene/population_kind.hpp"

#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace canopy;

namespace {

// A field of cells_x x cells_z unit cells from the origin, mirrored by `seed`, 60 wide blades.
Scene field_scene(const std::string& camera, int cells_x, int cells_z, int seed = 1, double density = 1.0) {
    return parse_scene(
        std::string("[scene]\nname = \"field\"\nambient = 0.2\n") + camera +
            "\n[[light]]\ntype = \"directional\"\ndirection = [-0.3, -1, -0.2]\ncasts_shadows = false\n"
            "[[population]]\nname = \"field\"\nkind = \"grass\"\nalbedo = [0.1, 0.8, 0.1]\n"
            "params = { cells_x = " +
            std::to_string(cells_x) + ", cells_z = " + std::to_string(cells_z) +
            ", centre_x = " + std::to_string(0.5 * cells_x) + ", centre_z = " + std::to_string(0.5 * cells_z) +
            ", mirror = true, mirror_seed = " + std::to_string(seed) + ", density = " + std::to_string(density) +
            ", blades = 60, subdivisions = 3, width_min = 0.06, width_max = 0.1 }\n",
        "field.toml");
}

Image render(const Scene& scene, const std::string& technique, int macro, int width, int height,
             const std::string& mip_filter = "coverage") {
    std::map<std::string, ParamValue> params{{"macro_cells", (long long)macro}, {"resolution", 128ll},
                                             {"mip_filter", mip_filter}};
    if (mip_filter == "none") params["bake_supersampling"] = 1ll;
    if (technique == "grass.volume") {
        params["slices"] = 4ll;
        params["height_resolution"] = 48ll;
    }
    return test::render_technique(scene, technique, params, width, height);
}

// Pixels where two images differ by more than `tolerance` in a channel.
int differing_pixels(const Image& a, const Image& b, float tolerance = 1e-3f) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            bool differ = false;
            for (int c = 0; c < 3; ++c) differ = differ || std::abs(a.at(x, y)[c] - b.at(x, y)[c]) > tolerance;
            n += differ;
        }
    return n;
}

}  // namespace

TEST_CASE("macro-cells: they tile the field, every cell exactly once, the last ones cut at the far edges") {
    for (const glm::uvec2 cells : {glm::uvec2(7, 5), glm::uvec2(1, 1), glm::uvec2(32, 32), glm::uvec2(3, 8)})
        for (uint32_t k : {1u, 2u, 3u, 4u, 16u}) {
            CAPTURE(cells.x);
            CAPTURE(cells.y);
            CAPTURE(k);
            const std::vector<grass::MacroInstance> macros = grass::macro_instances(cells, k);
            CHECK(macros.size() == grass::macro_count(cells, k));
            std::vector<int> seen(size_t(cells.x) * cells.y, 0);
            for (const glm::vec4 m : macros) {
                CHECK(m.z >= 1.0f);
                CHECK(m.z <= float(k));
                CHECK(m.w <= float(k));
                for (int z = int(m.y); z < int(m.y + m.w); ++z)
                    for (int x = int(m.x); x < int(m.x + m.z); ++x) {
                        REQUIRE(x < int(cells.x));
                        REQUIRE(z < int(cells.y));
                        ++seen[size_t(z) * cells.x + size_t(x)];
                    }
            }
            for (int s : seen) CHECK(s == 1);
        }
    CHECK(grass::macro_count({32, 32}, 16) == 4);
    CHECK(grass::macro_count({7, 5}, 4) == 4);
}

TEST_CASE("macro-cells: a point's cell and mirrored patch point, as eq 6.6 puts them inside cells and on their edges") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> in_macro(0.0f, 3.0f);
    const glm::ivec2 first(5, 2), span(3, 3);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec2 u = glm::vec2(first) + glm::vec2(in_macro(rng), in_macro(rng));
        const glm::vec2 s((i & 1) ? -1.0f : 1.0f, (i & 2) ? -1.0f : 1.0f);
        const glm::ivec2 cell = shader::grass_macro_cell(u, first, span);
        CHECK(cell == glm::ivec2(glm::floor(u)));
        const glm::vec2 p = shader::grass_macro_patch_point(u, cell, s);
        const glm::vec2 eq66 = shader::grass_mirror_slice_uv(u, s) - glm::floor(u);
        CHECK(std::abs(p.x - eq66.x) < 1e-5f);
        CHECK(std::abs(p.y - eq66.y) < 1e-5f);
    }
    // The macro-cell's far edges belong to its last cells, and map to the patch's edges.
    const glm::vec2 far_corner = glm::vec2(first + span);
    CHECK(shader::grass_macro_cell(far_corner, first, span) == first + span - glm::ivec2(1));
    CHECK(shader::grass_macro_patch_point(far_corner, first + span - glm::ivec2(1), {1.0f, -1.0f}) == glm::vec2(1.0f, 0.0f));
    // A mirrored cell shows slice n-1-k at its plane k: the plane's centre mirrored about the patch's.
    const int n = 8;
    for (int k = 0; k < n; ++k) {
        CHECK(shader::grass_macro_slice(k, n, 1.0f) == k);
        const int mirrored = shader::grass_macro_slice(k, n, -1.0f);
        CHECK((float(mirrored) + 0.5f) / n == doctest::Approx(1.0f - (float(k) + 0.5f) / n));
    }
    CHECK(shader::grass_mirror_vector({0.3f, 0.8f, -0.5f}, {-1.0f, 1.0f}) == glm::vec3(-0.3f, 0.8f, -0.5f));
}

TEST_CASE("macro-cells: a cell's record holds its own mirror signs and its copy's corner densities") {
    const Scene scene = field_scene("[camera]\nposition = [2, 3, 6]\ntarget = [2, 0, 1]", 4, 3, 7, 0.6);
    const Population& population = scene.populations.at(0);
    const grass::GrassPopulationSpec spec = grass::grass_population_spec(population.params);
    const std::vector<PopulationInstance> copies = *generate_instances(population);
    const std::vector<shader::GrassCell> cells = grass::grass_cells(spec.field, copies);
    REQUIRE(cells.size() == 12);
    int mirrored = 0;
    for (size_t c = 0; c < cells.size(); ++c) {
        const glm::ivec2 cell(int(c % 4), int(c / 4));
        const glm::vec2 s = grass::mirror_signs(spec.field, cell);
        CHECK(glm::vec2(cells[c].signs) == s);
        CHECK(cells[c].densities == copies[c].data);
        // The copy's own placement mirrors by the same signs (its matrix's diagonal).
        CHECK(std::signbit(copies[c].model[0][0]) == (s.x < 0.0f));
        CHECK(std::signbit(copies[c].model[2][2]) == (s.y < 0.0f));
        mirrored += s.x < 0.0f || s.y < 0.0f;
    }
    CHECK(mirrored >= 4);  // the check sees mirrored cells
    CHECK_THROWS_AS(grass::grass_cells(spec.field, std::span(copies).first(5)), std::logic_error);
}

TEST_CASE("macro-cells: grass.image and grass.volume draw the same field whatever the macro size") {
    // Oblique, over a field of 5 x 4 cells: macro sizes 2 and 3 leave cut macro-cells at the far edges.
    const Scene scene = field_scene("[camera]\nposition = [2.5, 2.2, 7.5]\ntarget = [2.5, 0, 2]\nfov = 50", 5, 4);
    for (const std::string technique : {"grass.image", "grass.volume"}) {
      for (const std::string filter : {"none", "coverage"}) {
        CAPTURE(technique);
        CAPTURE(filter);
        const Image one = render(scene, technique, 1, 200, 120, filter);
        const int grass = grass::test::grass_pixels(one);
        CAPTURE(grass);
        CHECK(grass > 200 * 120 / 40);
        for (int k : {2, 3, 8}) {
            CAPTURE(k);
            const Image macro = render(scene, technique, k, 200, 120, filter);
            if (filter == "none" || technique == "grass.image") {
                CHECK(differing_pixels(one, macro) <= grass / 500);
            } else {
                // A filtered texel is partly transparent: a ray that gathers enough of it in one
                // cell's cuboid stops there, where a macro-cell's walk goes on into the next cell
                // and composites what it meets. Colours move a little along the cells' edges (at
                // k = 8, 258 pixels by 0.05), few by much (15 by 0.2).
                CHECK(differing_pixels(one, macro, 0.2f) <= grass / 100);
            }
            for (float v : macro.pixels) REQUIRE(std::isfinite(v));
        }
      }
    }
}

// Of seeds 2-40, the one whose mirror signs differ from seed 1's in the most cells (both axes).
int most_different_seed(int cells_x, int cells_z) {
    const auto signs = [&](int seed, glm::ivec2 cell) {
        grass::GrassField field;
        field.cells = glm::uvec2(cells_x, cells_z);
        field.mirror_seed = uint32_t(seed);
        return grass::mirror_signs(field, cell);
    };
    int best = 2, most = -1;
    for (int seed = 2; seed <= 40; ++seed) {
        int differ = 0;
        for (int z = 0; z < cells_z; ++z)
            for (int x = 0; x < cells_x; ++x) {
                const glm::vec2 a = signs(1, {x, z}), b = signs(seed, {x, z});
                differ += (a.x != b.x) + (a.y != b.y);
            }
        if (differ > most) best = seed, most = differ;
    }
    return best;
}

TEST_CASE("macro-cells: seen from afar, the mirrored cells cover what the reference's rays hit, and no other mirror's") {
    struct View {
        std::string technique, camera;
        int cells_x, cells_z, width, height;
    };
    // From far above (the top view), and for the volume from far along -z and -x (its slices),
    // where the depth of the first blade shows a cell's mirror along the view too.
    const std::vector<View> views{
        {"grass.image", "[camera]\nposition = [1.5, 200, 1]\ntarget = [1.5, 0, 1]\nup = [0, 0, -1]\nfov = 0.7\nnear = 150\nfar = 250",
         3, 2, 480, 320},
        {"grass.volume", "[camera]\nposition = [2, 0.14, 300]\ntarget = [2, 0.14, 0.5]\nfov = 0.08\nnear = 250\nfar = 350",
         4, 1, 600, 56},
        {"grass.volume", "[camera]\nposition = [300, 0.14, 2]\ntarget = [0.5, 0.14, 2]\nfov = 0.08\nnear = 250\nfar = 350",
         1, 4, 600, 56},
    };
    for (const View& v : views) {
        CAPTURE(v.technique);
        CAPTURE(v.camera);
        const Scene scene = field_scene(v.camera, v.cells_x, v.cells_z, 1);
        std::map<std::string, ParamValue> params{{"macro_cells", 2ll}, {"resolution", 256ll}};
        if (v.technique == "grass.volume") {
            params["slices"] = 8ll;
            params["height_resolution"] = 64ll;
        }
        const Technique* technique = TechniqueRegistry::instance().find(v.technique);
        REQUIRE(technique);
        FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), uint32_t(v.width), uint32_t(v.height),
                               technique->graph(ParamSet::resolve(technique->params(), params, {}, {}, v.technique)));
        renderer.render();
        const auto [image, visibility] = renderer.read_color_and_pixel_visibility();
        // Half a section's width (the slice lies at its centre) and a texel.
        const float depth_tolerance = 0.5f / 8.0f + 0.01f;
        const grass::test::CoverageAgreement same =
            grass::test::compare_with_reference_hits(scene, image, &visibility, depth_tolerance);
        const Scene other_scene = field_scene(v.camera, v.cells_x, v.cells_z, most_different_seed(v.cells_x, v.cells_z));
        const grass::test::CoverageAgreement other =
            grass::test::compare_with_reference_hits(other_scene, image, &visibility, depth_tolerance);
        CAPTURE(same.compared);
        CAPTURE(same.covered);
        CAPTURE(same.differ);
        CAPTURE(same.depth_compared);
        CAPTURE(same.depth_off);
        CAPTURE(other.differ);
        CAPTURE(other.depth_compared);
        CAPTURE(other.depth_off);
        CHECK(same.covered > 500);
        // The tiled bake cuts blades leaning out of a cell and brings in those of neighbours
        // mirrored as the cell is (Boulanger §4.2.3 tiles one unmirrored patch), so pixels along
        // the edges between cells that mirror differently differ: 2.1 % of those compared from
        // above, 1.4 % along -z (and 5.4 % of the volume's depths are off by more than half a
        // section there).
        CHECK(same.differ <= same.compared / 40);
        // The image's depth is its slice's, not the blade's; the volume's is the first blade's.
        const bool depth = v.technique == "grass.volume";
        const int same_wrong = same.differ + (depth ? same.depth_off : 0);
        const int other_wrong = other.differ + (depth ? other.depth_off : 0);
        CHECK(other_wrong >= 3 * same_wrong);
        if (depth) CHECK(same.depth_off <= same.depth_compared / 10);
    }
}

TEST_CASE("macro-cells on a terrain: the grid heights are the copies' corner heights, and uneven macro-cells split "
          "until their unplanarity is under the threshold") {
    const Scene hills = grass::test::hills_scene("[camera]\nposition = [0, 7, 3.5]\ntarget = [0, 0.3, 0]", 1.2);
    const Population& population = hills.populations.at(0);
    const grass::GrassPopulationSpec spec = grass::grass_population_spec(population.params, population.ground);
    const std::vector<PopulationInstance> copies = *generate_instances(population);
    const glm::uvec2 cells = spec.field.cells;
    const std::vector<float> grid = grass::grid_heights(spec.field, copies);
    REQUIRE(grid.size() == size_t(cells.x + 1) * (cells.y + 1));
    for (uint32_t z = 0; z < cells.y; ++z)
        for (uint32_t x = 0; x < cells.x; ++x) {
            CAPTURE(x);
            CAPTURE(z);
            const glm::vec4 h = grass::cell_corner_heights(spec.field, glm::ivec2(int(x), int(z)));
            const auto at = [&](uint32_t gx, uint32_t gz) { return grid[size_t(gz) * (cells.x + 1) + gx]; };
            CHECK(at(x, z) == doctest::Approx(h.x).epsilon(1e-5));
            CHECK(at(x + 1, z) == doctest::Approx(h.y).epsilon(1e-5));
            CHECK(at(x, z + 1) == doctest::Approx(h.z).epsilon(1e-5));
            CHECK(at(x + 1, z + 1) == doctest::Approx(h.w).epsilon(1e-5));
        }

    // A tilted plane is bilinear: no macro-cell is uneven. A bump in the middle is not.
    const glm::uvec2 five(5, 5);
    std::vector<float> plane(36), bump(36, 0.0f);
    for (uint32_t z = 0; z <= 5; ++z)
        for (uint32_t x = 0; x <= 5; ++x) plane[z * 6 + x] = 0.3f * float(x) - 0.1f * float(z);
    bump[2 * 6 + 2] = 0.5f;
    CHECK(grass::macro_unplanarity(plane, five, grass::MacroInstance(0, 0, 5, 5)) == doctest::Approx(0.0f).epsilon(1e-6));
    CHECK(grass::macro_unplanarity(bump, five, grass::MacroInstance(0, 0, 5, 5)) == doctest::Approx(0.5f));
    CHECK(grass::macro_unplanarity(bump, five, grass::MacroInstance(3, 3, 2, 2)) == 0.0f);  // away from the bump
    CHECK(grass::macro_unplanarity(bump, five, grass::MacroInstance(1, 1, 1, 1)) == 0.0f);  // one cell

    // The height range spans the macro-cell's grid vertices, its edges included, and no others.
    const glm::vec2 tilted = grass::macro_height_range(plane, five, grass::MacroInstance(1, 2, 2, 3));
    CHECK(tilted.x == doctest::Approx(0.3 - 0.5).epsilon(1e-6));
    CHECK(tilted.y == doctest::Approx(0.9 - 0.2).epsilon(1e-6));
    CHECK(grass::macro_height_range(bump, five, grass::MacroInstance(0, 0, 2, 2)) == glm::vec2(0.0f, 0.5f));
    CHECK(grass::macro_height_range(bump, five, grass::MacroInstance(3, 0, 2, 5)) == glm::vec2(0.0f, 0.0f));
    CHECK(grass::macro_instances_on_terrain(five, 4, plane, 0.01f) == grass::macro_instances(five, 4));
    for (const float threshold : {0.0f, 0.1f, 0.6f}) {
        CAPTURE(threshold);
        const std::vector<grass::MacroInstance> parts = grass::macro_instances_on_terrain(five, 4, bump, threshold);
        std::vector<int> covered(25, 0);
        for (const grass::MacroInstance& m : parts) {
            CAPTURE(glm::uvec4(m));
            CHECK((grass::macro_unplanarity(bump, five, m) <= threshold || (m.z == 1 && m.w == 1)));
            for (uint32_t z = m.y; z < uint32_t(m.y + m.w); ++z)
                for (uint32_t x = m.x; x < uint32_t(m.x + m.z); ++x) ++covered[z * 5 + x];
        }
        CHECK(std::all_of(covered.begin(), covered.end(), [](int n) { return n == 1; }));
        if (threshold >= 0.5f)
            CHECK(parts.size() == grass::macro_instances(five, 4).size());
        else
            CHECK(parts.size() > grass::macro_instances(five, 4).size());
    }
}

TEST_CASE("macro-cells on a terrain: grass.image's macro quads, lifted at their corners, cover the reference's lifted "
          "blades as its per-cell quads do") {
    // From high above at an angle, as grass.image's own terrain test (per-cell quads: 1.38 times the
    // flat field's error); 2 x 2 macro-cells. Measured: split where uneven (the default 0.05), 1.43
    // times; never split (Lemme's bilinear flattening over every macro-cell), 1.57 times. Corners
    // not lifted read 3.1 times; the quad not split along the ground's diagonal 1.86 and 2.16 times.
    const char* camera = "[camera]\nposition = [0.0, 7.0, 3.5]\ntarget = [0.0, 0.3, 0.0]\nfov = 40";
    for (const auto& [unplanarity, bound] : {std::pair{0.05, 1.5}, std::pair{10.0, 1.7}}) {
        CAPTURE(unplanarity);
        grass::test::check_follows_terrain(camera, bound, [&](const Scene& scene) {
            return test::render_technique(scene, "grass.image",
                                          {{"macro_cells", 2ll}, {"resolution", 128ll}, {"macro_unplanarity", unplanarity}},
                                          200, 120);
        });
    }
}

TEST_CASE("macro-cells on a terrain: grass.volume's macro cuboids span their ground and their rays read it, covering "
          "the reference's lifted blades as its per-cell cuboids do") {
    // The camera of grass.volume's own terrain test (per-cell cuboids: at most 1.1 times the flat
    // field's error). Measured with 2 x 2 macro-cells: 0.81 times; 4.2 times with the lookup not
    // shifted by the ground, 4.7 times with the cuboids not spanning it.
    const char* camera = "[camera]\nposition = [0.0, 3.2, 5.0]\ntarget = [0.0, 0.5, 0.0]\nfov = 45";
    const std::map<std::string, ParamValue> params{
        {"macro_cells", 2ll}, {"slices", 8ll}, {"resolution", 128ll}, {"height_resolution", 64ll}};
    grass::test::check_follows_terrain(camera, 1.1, [&](const Scene& scene) {
        return test::render_technique(scene, "grass.volume", params, 200, 120);
    }, 1500);
    // The terrain's buffers cost nothing on flat ground: 16 bytes each, a float a grid vertex and
    // a range a macro-cell on the hills.
    const Technique& volume = *TechniqueRegistry::instance().find("grass.volume");
    for (const bool on_terrain : {false, true}) {
        CAPTURE(on_terrain);
        Scene scene = grass::test::hills_scene(camera, 1.2);
        if (!on_terrain) scene.populations.at(0).ground.terrain = nullptr;  // the field flat beside the hills
        FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), 32, 24,
                               volume.graph(ParamSet::resolve(volume.params(), params, {}, {}, "grass.volume")));
        renderer.render();
        const size_t heights = renderer.read_buffer("field_heights").size(), ranges = renderer.read_buffer("macro_ranges").size();
        CHECK(heights == (on_terrain ? sizeof(float) * (2 * grass::kMaxFieldSide + 1 + 16) : 16));
        CHECK(ranges == (on_terrain ? sizeof(glm::vec2) * 16 : 16));
    }
}
