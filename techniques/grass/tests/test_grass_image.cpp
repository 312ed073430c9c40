// grass.image (Lemme's horizontal slice): its load-phase bake is the top view of the very blades
// the reference traces (checked texel by texel against Embree's vertical rays: which blade, its
// threshold, a unit normal turned up), and seen from far above, the slices cover what the
// reference's rays hit. A flipped bake, a slice quad with its coordinates swapped or a cut that
// ignores the density fails a check here.
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

constexpr uint32_t kBake = 128;
const char* kAnyCamera = "[camera]\nposition = [0.5, 1.0, 2.5]\ntarget = [0.5, 0.0, 0.5]";
// Far above the cell with a narrow view: nearly the bake's orthographic view from above.
const char* kFarAbove =
    "[camera]\nposition = [0.5, 80, 0.5]\ntarget = [0.5, 0, 0.5]\nup = [0, 0, -1]\nfov = 0.9\nnear = 40\nfar = 120";

const Technique& image_technique() {
    const Technique* t = TechniqueRegistry::instance().find("grass.image");
    REQUIRE(t);
    return *t;
}

// Level 0 alone, unfiltered (mip_filter = "none", bake_supersampling = 1): each texel one blade,
// as the texel-by-texel checks against the rays need; filtering is test_grass_coverage's and
// test_mip_filters'.
FrameRenderer renderer_for(const Scene& scene, uint32_t width, uint32_t height, double slice_height = 0.1) {
    const ParamSet params = ParamSet::resolve(image_technique().params(),
                                              {{"resolution", (long long)kBake},
                                               {"slice_height", slice_height},
                                               {"mip_filter", std::string("none")},
                                               {"bake_supersampling", 1LL}},
                                              {}, {}, "grass.image");
    return FrameRenderer(test::gpu(), scene, build_scene_meshes(scene), width, height, image_technique().graph(params));
}

}  // namespace

TEST_CASE("grass.image: the top-view bake shows, texel by texel, the blade a vertical ray hits, its threshold and normal") {
    const Scene scene = one_cell_scene(kAnyCamera, "density = 1.0");
    FrameRenderer renderer = renderer_for(scene, 64, 48);
    renderer.render();
    const Image albedo = renderer.read_image("slice_albedo");
    const Image normal = renderer.read_image("slice_normal");
    const Image blades = renderer.read_image("slice_blades");
    REQUIRE(albedo.width == int(kBake));
    const auto truth = grass::test::traced_bake(scene, grass::test::View::down, kBake);
    const grass::test::BakeAgreement same = grass::test::compare_bake(albedo, blades, truth);
    CAPTURE(same.compared);
    CAPTURE(same.covered);
    CHECK(same.covered > 300);
    CHECK(same.coverage == 0);
    CHECK(same.threshold == 0);
    CHECK(same.root == 0);  // the blade map holds each blade's root, where its band is taken
    CHECK(grass::test::compare_bake(albedo, blades, truth, true).coverage > 100);
    // Where a blade is baked, its normal is a unit vector turned to the sky (the side the bake saw).
    int normals = 0;
    for (int j = 0; j < int(kBake); ++j)
        for (int i = 0; i < int(kBake); ++i) {
            // Level 0 is not anti-aliased: a texel shows a blade or none.
            CHECK((albedo.at(i, j)[3] == 1.0f || albedo.at(i, j)[3] == 0.0f));
            if (albedo.at(i, j)[3] == 0.0f) continue;
            const float* n = normal.at(i, j);
            CHECK(std::abs(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0f) < 2e-3f);
            CHECK(n[1] >= 0.0f);
            ++normals;
        }
    CHECK(normals > 300);
    for (float v : albedo.pixels) REQUIRE(std::isfinite(v));
}

TEST_CASE("grass.image: seen from far above, the slices cover what the reference's rays hit") {
    const Scene scene = one_cell_scene(kFarAbove, "density = 1.0");
    FrameRenderer renderer = renderer_for(scene, 160, 120);
    renderer.render();
    const grass::test::CoverageAgreement a = grass::test::compare_with_reference_hits(scene, renderer.read_color());
    CAPTURE(a.compared);
    CAPTURE(a.covered);
    CAPTURE(a.differ);
    CHECK(a.covered > 300);
    CHECK(a.differ <= a.compared / 100);
}

TEST_CASE("grass.image on a terrain: quads lifted at their corners and split along the ground's diagonal cover the "
          "reference's lifted blades as well as on flat ground") {
    // From high above at an angle (the image is a far representation); height_scale 0 is the same
    // field flat. The check compares the per-tile coverage error with the flat field's.
    const char* camera = "[camera]\nposition = [0.0, 7.0, 3.5]\ntarget = [0.0, 0.3, 0.0]\nfov = 40";
    // Measured 1.38 x: a top view baked on flat ground, laid on a slope, still misses some blades.
    // Quads split along their own diagonal read 1.64 x, quads not lifted 2.46 x.
    grass::test::check_follows_terrain(camera, 1.5, [](const Scene& scene) {
        FrameRenderer renderer = renderer_for(scene, 200, 120);
        renderer.render();
        return renderer.read_color();
    });
}

TEST_CASE("grass.image: a thinner field cuts the baked blades whose threshold the density does not reach") {
    const auto coverage = [](const std::string& density, int* kept_texels, int* texels) {
        const Scene scene = one_cell_scene(kFarAbove, density);
        FrameRenderer renderer = renderer_for(scene, 160, 120);
        renderer.render();
        const Image colour = renderer.read_image("slice_albedo");
        const Image baked = renderer.read_image("slice_blades");
        *texels = *kept_texels = 0;
        for (size_t i = 0; i < baked.pixels.size(); i += 4) {
            if (colour.pixels[i + 3] == 0.0f) continue;
            ++*texels;
            *kept_texels += baked.pixels[i] <= 0.3f;
        }
        return grass::test::grass_pixels(renderer.read_color());
    };
    int kept = 0, texels = 0, kept_sparse = 0, texels_sparse = 0;
    const int all = coverage("density = 1.0", &kept, &texels);
    const int thinned = coverage("density = 0.3", &kept_sparse, &texels_sparse);
    CHECK(texels_sparse == texels);  // the bake does not depend on the density
    const double share = double(kept) / double(texels);
    CAPTURE(share);
    CHECK(share > 0.1);
    CHECK(share < 0.7);
    CHECK(double(thinned) / double(all) == doctest::Approx(share).epsilon(0.1));
}
