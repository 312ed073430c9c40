// grass.volume (Lemme's ray-cast slices): each slice's load-phase bake holds, texel by texel, the
// blade Embree's orthographic rays meet within that slice's section (which blade, its
// threshold); seen from afar along either slice direction, the volumes cover what the
// reference's rays hit, at about the depth they hit it; an eye inside a cell's cuboid still sees
// its blades. A slice baked from the wrong section, a swapped layer or texel axis, a depth left at
// the cuboid's face or the entry faces drawn (Lemme's) fails a check here.
#include "support/bake_truth.hpp"

#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace canopy;
using grass::test::one_cell_scene;

namespace {

constexpr uint32_t kSlices = 4;
constexpr uint32_t kWidth = 96, kHeight = 48;
const char* kAnyCamera = "[camera]\nposition = [0.5, 1.0, 2.5]\ntarget = [0.5, 0.0, 0.5]";
// Far away and low, with a narrow view: nearly the orthographic view along -z (or -x).
const char* kFarAlongZ =
    "[camera]\nposition = [0.5, 0.12, 80]\ntarget = [0.5, 0.12, 0.5]\nfov = 0.9\nnear = 40\nfar = 120";
const char* kFarAlongX =
    "[camera]\nposition = [80, 0.12, 0.5]\ntarget = [0.5, 0.12, 0.5]\nfov = 0.9\nnear = 40\nfar = 120";
// Inside the cell's cuboid, among the blades, looking along it.
const char* kInside = "[camera]\nposition = [0.05, 0.06, 0.1]\ntarget = [1, 0.04, 0.7]\nnear = 0.001\nfov = 60";

const Technique& volume_technique() {
    const Technique* t = TechniqueRegistry::instance().find("grass.volume");
    REQUIRE(t);
    return *t;
}

// Level 0 alone, unfiltered (mip_filter = "none", bake_supersampling = 1): each texel one blade,
// as the texel-by-texel checks against the rays need; filtering is test_grass_coverage's and
// test_mip_filters'.
FrameRenderer renderer_for(const Scene& scene, uint32_t width, uint32_t height, uint32_t slices = kSlices) {
    const ParamSet params = ParamSet::resolve(volume_technique().params(),
                                              {{"slices", (long long)slices},
                                               {"resolution", (long long)kWidth},
                                               {"height_resolution", (long long)kHeight},
                                               {"mip_filter", std::string("none")},
                                               {"bake_supersampling", 1LL}},
                                              {}, {}, "grass.volume");
    return FrameRenderer(test::gpu(), scene, build_scene_meshes(scene), width, height, volume_technique().graph(params));
}

Bounds prototype_bounds(const Scene& scene) {
    Bounds b;
    for (const Vertex& v : scene.populations.at(0).family->prototype.vertices) b.extend(v.position);
    return b;
}

}  // namespace

TEST_CASE("grass.volume: each slice's bake shows the blades of its own section, texel by texel") {
    const Scene scene = one_cell_scene(kAnyCamera, "density = 1.0");
    FrameRenderer renderer = renderer_for(scene, 64, 48);
    renderer.render();
    const Bounds b = prototype_bounds(scene);
    int covered = 0;
    for (uint32_t axis = 0; axis < 2; ++axis)
        for (uint32_t k = 0; k < kSlices; ++k) {
            CAPTURE(axis);
            CAPTURE(k);
            const Image albedo = renderer.read_image("slices_albedo", 0, axis * kSlices + k);
            const Image blades = renderer.read_image("slices_blades", 0, axis * kSlices + k);
            REQUIRE(albedo.width == int(kWidth));
            REQUIRE(albedo.height == int(kHeight));
            // Sections split the prototype's bounds in x (slices along x) or z into equal parts.
            const float lo = axis == 0 ? b.min.x : b.min.z, hi = axis == 0 ? b.max.x : b.max.z;
            const float step = (hi - lo) / float(kSlices);
            grass::test::Section section{k == 0 ? -1e30f : lo + step * float(k),
                                         k + 1 == kSlices ? 1e30f : lo + step * float(k + 1)};
            const auto view = axis == 0 ? grass::test::View::along_x : grass::test::View::along_z;
            const auto truth = grass::test::traced_bake(scene, view, kWidth, kHeight, section);
            const grass::test::BakeAgreement same = grass::test::compare_bake(albedo, blades, truth);
            CAPTURE(same.compared);
            CAPTURE(same.covered);
            CAPTURE(same.coverage);
            // Where a blade crosses a section's plane, the bake's interpolated position and the
            // ray's hit may fall on either side: a texel or two at most (none seen).
            CHECK(same.coverage <= same.compared / 1000);
            CHECK(same.threshold <= same.compared / 1000);
            CHECK(same.root <= same.compared / 1000);
            covered += same.covered;
            // The neighbouring section's blades are not this one's.
            if (k + 1 < kSlices) {
                const grass::test::Section next{section.hi, k + 2 == kSlices ? 1e30f : lo + step * float(k + 2)};
                const auto other = grass::test::traced_bake(scene, view, kWidth, kHeight, next);
                CHECK(grass::test::compare_bake(albedo, blades, other).coverage > same.coverage + 20);
            }
            for (float v : albedo.pixels) REQUIRE(std::isfinite(v));
        }
    CHECK(covered > 1000);
}

TEST_CASE("grass.volume: seen from afar along either slice direction, the volume covers what the reference's rays hit") {
    for (const char* camera : {kFarAlongZ, kFarAlongX}) {
        CAPTURE(camera);
        const Scene scene = one_cell_scene(camera, "density = 1.0");
        FrameRenderer renderer = renderer_for(scene, 160, 120);
        renderer.render();
        const auto [color, visibility] = renderer.read_color_and_pixel_visibility();
        // The depth written is the blade's, not the cuboid's face: within half a section's width
        // (the slice lies at its centre) and a texel of the reference's hit.
        const Bounds b = prototype_bounds(scene);
        const float tolerance = 0.5f * (b.max.x - b.min.x) / float(kSlices) + 0.01f;
        const grass::test::CoverageAgreement a =
            grass::test::compare_with_reference_hits(scene, color, &visibility, tolerance);
        CAPTURE(a.compared);
        CAPTURE(a.covered);
        CAPTURE(a.differ);
        CAPTURE(a.depth_compared);
        CAPTURE(a.depth_off);
        CHECK(a.covered > 300);
        CHECK(a.differ <= a.compared / 1000);
        CHECK(a.depth_compared > 300);
        CHECK(a.depth_off <= a.depth_compared / 100);
    }
}

TEST_CASE("grass.volume on a terrain: the stretched cuboid and the shifted lookup cover the reference's lifted blades "
          "as well as on flat ground") {
    // Seen obliquely; height_scale 0 is the same field flat. The slices approximate the blades
    // (and the lookup reads the ground under the hit, not under each root, eq 6.16), so the check
    // compares the per-tile coverage error with the flat field's.
    const char* camera = "[camera]\nposition = [0.0, 3.2, 5.0]\ntarget = [0.0, 0.5, 0.0]\nfov = 45";
    // A lookup that ignores the cells' mirrors reads 1.2 x flat.
    grass::test::check_follows_terrain(camera, 1.1, [](const Scene& scene) {
        FrameRenderer renderer = renderer_for(scene, 200, 120, 8);
        renderer.render();
        return renderer.read_color();
    }, 1500);
}

TEST_CASE("grass.volume: an eye inside a cell's cuboid sees the blades around it") {
    const Scene scene = one_cell_scene(kInside, "density = 1.0");
    FrameRenderer renderer = renderer_for(scene, 96, 64, 8);
    renderer.render();
    const Image color = renderer.read_color();
    for (float v : color.pixels) REQUIRE(std::isfinite(v));
    const grass::test::CoverageAgreement a = grass::test::compare_with_reference_hits(scene, color);
    const int drawn = grass::test::grass_pixels(color);
    CAPTURE(a.compared);
    CAPTURE(a.covered);
    CAPTURE(a.differ);
    CAPTURE(drawn);
    CHECK(a.covered > 500);
    // Slices place a blade anywhere in its section: near the eye that moves it across many
    // pixels, so only the amount of grass is held to the reference's.
    CHECK(drawn > a.covered / 2);
}
