// grass.lod (blades near, volume or BTF slices in the middle, image far, split by density
// thresholds): with its bands pushed to either end it draws exactly what grass.geometry,
// grass.volume, grass.slices or grass.image draws alone, so a band that a representation ignores or takes from another shows; with the
// blades split between two bands (half each), the two together cover from above what the
// reference's rays hit, no blade dropped, and each band draws its part; across a field whose cells
// lie in all three bands the image is finite and its coverage no worse than the representations'.
#include "support/bake_truth.hpp"
#include "support/cpu_checks.hpp"
#include "support/lod_field.hpp"

#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "reference/reference_renderer.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>

using namespace canopy;
using grass::test::lod_field_scene;
using grass::test::max_difference;
using grass::test::one_cell_scene;

namespace {

using Values = std::map<std::string, ParamValue>;

const char* kFarAbove =
    "[camera]\nposition = [0.5, 80, 0.5]\ntarget = [0.5, 0, 0.5]\nup = [0, 0, -1]\nfov = 0.9\nnear = 40\nfar = 120";

Image render(const Scene& scene, const std::string& technique, const Values& values, uint32_t w = 160, uint32_t h = 96) {
    const Technique* t = TechniqueRegistry::instance().find(technique);
    REQUIRE(t);
    const ParamSet params = ParamSet::resolve(t->params(), values, {}, {}, technique);
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), w, h, t->graph(params));
    renderer.render();
    return renderer.read_color();
}

// The representations' parameters as grass.lod names them, one sample, alpha-tested blades.
Values lod_values(double geometry_full, double geometry_none, double image_start, double image_full) {
    return {{"geometry_full", geometry_full}, {"geometry_none", geometry_none}, {"image_start", image_start},
            {"image_full", image_full},       {"samples", 1LL},                 {"coverage", std::string("alpha_test")},
            {"slices", 4LL},                  {"resolution", 96LL},             {"height_resolution", 48LL},
            {"image_resolution", 128LL}};
}

}  // namespace

TEST_CASE("grass.lod: with its bands at either end it draws what each representation draws alone") {
    const Scene scene = lod_field_scene();
    const Image blades = render(scene, "grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}});
    const Image volume = render(scene, "grass.volume", {{"slices", 4LL}, {"resolution", 96LL}, {"height_resolution", 48LL}});
    const Image image = render(scene, "grass.image", {{"resolution", 128LL}});
    // Every band at 1e6: all blades; at 0: all image; the volume's between 0 and 1e6: all volume.
    const Image lod_blades = render(scene, "grass.lod", lod_values(1e6, 1e6, 1e6, 1e6));
    const Image lod_image = render(scene, "grass.lod", lod_values(0, 0, 0, 0));
    const Image lod_volume = render(scene, "grass.lod", lod_values(0, 0, 1e6, 1e6));
    CHECK(grass::test::grass_pixels(blades) > 1000);
    CHECK(grass::test::grass_pixels(volume) > 1000);
    CHECK(grass::test::grass_pixels(image) > 400);
    CHECK(max_difference(lod_blades, blades) <= 1e-5f);
    CHECK(max_difference(lod_volume, volume) <= 1e-5f);
    CHECK(max_difference(lod_image, image) <= 1e-5f);
    // The three differ from one another, so the checks above tell them apart.
    CHECK(max_difference(blades, volume) > 0.1f);
    CHECK(max_difference(blades, image) > 0.1f);
    // With Boulanger's middle band: all slices, as grass.slices draws them.
    // grass.lod filters every band by its one mip_filter (Lemme's by default), grass.slices by
    // Boulanger's max-alpha unless told.
    const Image slices = render(scene, "grass.slices",
                                {{"slices", 4LL}, {"resolution", 96LL}, {"height_resolution", 48LL}, {"mip_filter", std::string("coverage")}});
    Values btf = lod_values(0, 0, 1e6, 1e6);
    btf["middle"] = std::string("slices");
    const Image lod_slices = render(scene, "grass.lod", btf);
    CHECK(grass::test::grass_pixels(slices) > 1000);
    CHECK(max_difference(lod_slices, slices) <= 1e-5f);
    CHECK(max_difference(slices, volume) > 0.1f);
    // The shadowed bake too: grass.lod's middle_shadow_resolution is grass.slices' shadow_resolution.
    const Image shadowed = render(scene, "grass.slices",
                                  {{"slices", 4LL},
                                   {"resolution", 96LL},
                                   {"height_resolution", 48LL},
                                   {"shadow_resolution", 256LL},
                                   {"mip_filter", std::string("coverage")}});
    btf["middle_shadow_resolution"] = 256LL;
    CHECK(max_difference(render(scene, "grass.lod", btf), shadowed) <= 1e-5f);
    CHECK(max_difference(shadowed, slices) > 0.01f);  // the bake's shadows show: the check above tells them apart
    // Only the slices bake shadows: with the volume the parameter is refused.
    const Technique& lod = *TechniqueRegistry::instance().find("grass.lod");
    Values volume_shadowed = lod_values(0, 0, 1e6, 1e6);
    volume_shadowed["middle_shadow_resolution"] = 256LL;
    CHECK(lod.conflict(ParamSet::resolve(lod.params(), volume_shadowed, {}, {}, "grass.lod")));
    CHECK_FALSE(lod.conflict(ParamSet::resolve(lod.params(), btf, {}, {}, "grass.lod")));
    // and its blades and image bands unchanged.
    btf = lod_values(1e6, 1e6, 1e6, 1e6);
    btf["middle"] = std::string("slices");
    CHECK(max_difference(render(scene, "grass.lod", btf), blades) <= 1e-5f);
}

TEST_CASE("grass.lod: half the blades near and half far cover from above what the reference's rays hit") {
    // The eye is 80 away: geometry_none = 160 keeps about half of each threshold range as blades,
    // and image_start = image_full = 0 gives the rest to the image.
    const Scene scene = one_cell_scene(kFarAbove, "density = 1.0");
    const Image split = render(scene, "grass.lod", lod_values(0, 160, 0, 0), 160, 120);
    const Scene half = one_cell_scene(kFarAbove, "density = 0.5");
    const Image blades_half = render(half, "grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}}, 160, 120);
    for (float v : split.pixels) REQUIRE(std::isfinite(v));
    const grass::test::CoverageAgreement a = grass::test::compare_with_reference_hits(scene, split);
    CAPTURE(a.compared);
    CAPTURE(a.covered);
    CAPTURE(a.differ);
    CHECK(a.covered > 300);
    CHECK(a.differ <= a.compared / 500);
    // Both bands draw: the blades alone (those of threshold <= 0.5) cover clearly less.
    const int drawn = grass::test::grass_pixels(split), near_only = grass::test::grass_pixels(blades_half);
    CAPTURE(drawn);
    CAPTURE(near_only);
    CHECK(near_only > 100);
    CHECK(drawn > near_only + 100);
}

TEST_CASE("grass.lod: a field in all three bands renders finite, covering as the representations do") {
    const Scene scene = lod_field_scene();
    // Cells 1-5 m away: blades to 1.5-2.5, the volume to 3-4, the image beyond.
    Values values = lod_values(1.5, 2.5, 3.0, 4.0);
    values["samples"] = 4LL;
    values["coverage"] = std::string("alpha_to_coverage");
    const Image lod = render(scene, "grass.lod", values);
    for (float v : lod.pixels) REQUIRE(std::isfinite(v));
    values["middle"] = std::string("slices");
    const Image lod_btf = render(scene, "grass.lod", values);
    for (float v : lod_btf.pixels) REQUIRE(std::isfinite(v));
    const Image blades = render(scene, "grass.geometry", {{"samples", 4LL}});
    const Image image = render(scene, "grass.image", {{"resolution", 128LL}});
    const auto lod_agreement = grass::test::compare_with_reference_hits(scene, lod);
    const auto btf_agreement = grass::test::compare_with_reference_hits(scene, lod_btf);
    const auto blades_agreement = grass::test::compare_with_reference_hits(scene, blades);
    const auto image_agreement = grass::test::compare_with_reference_hits(scene, image);
    CAPTURE(lod_agreement.differ);
    CAPTURE(blades_agreement.differ);
    CAPTURE(image_agreement.differ);
    CAPTURE(lod_agreement.compared);
    CHECK(lod_agreement.covered > 150);
    MESSAGE("coverage differs at " << lod_agreement.differ << " (lod), " << blades_agreement.differ << " (blades), " << image_agreement.differ << " (image) of " << lod_agreement.compared);
    CHECK(lod_agreement.differ <= std::max(blades_agreement.differ, image_agreement.differ) + lod_agreement.compared / 50);
    CAPTURE(btf_agreement.differ);
    CHECK(btf_agreement.covered > 150);
    CHECK(btf_agreement.differ <= std::max(blades_agreement.differ, image_agreement.differ) + btf_agreement.compared / 50);
    CHECK(max_difference(lod, lod_btf) > 0.05f);  // the middle band differs
    // Neither all blades nor all image.
    CHECK(max_difference(lod, blades) > 0.1f);
    CHECK(max_difference(lod, image) > 0.1f);
}

TEST_CASE("grass.lod: culling each band's copies to its distances changes no pixel and drops cells from every band") {
    const Scene scene = lod_field_scene();
    const Technique* t = TechniqueRegistry::instance().find("grass.lod");
    REQUIRE(t);
    for (const std::string middle : {"volume", "slices"}) {
        CAPTURE(middle);
        // Cells' centres 2.2-4.6 m away, their boxes' points 1.7-5 m: blades to 2-2.6 m, the middle band
        // 2-3.4 m, the image from 3 m; the first row is too near for the image, the last too far
        // for the middle band and the blades.
        Values values = lod_values(2.0, 2.6, 3.0, 3.4);
        values["middle"] = middle;
        values["culling"] = std::string("none");
        const Image whole = render(scene, "grass.lod", values);
        values["culling"] = std::string("gpu");
        FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), 160, 96,
                               t->graph(ParamSet::resolve(t->params(), values, {}, {}, "grass.lod")));
        renderer.render();
        CHECK(max_difference(renderer.read_color(), whole) <= 1e-5f);
        CHECK(grass::test::grass_pixels(whole) > 1000);
        // Each band's survivors: some of the 9 cells, not all.
        uint32_t total = 0;
        for (const std::string arguments : {"draw_arguments", "middle_draw_arguments", "far_draw_arguments"}) {
            CAPTURE(arguments);
            const std::vector<std::byte> bytes = renderer.read_buffer(arguments);
            REQUIRE(bytes.size() >= sizeof(VkDrawIndexedIndirectCommand));
            VkDrawIndexedIndirectCommand draw;
            std::memcpy(&draw, bytes.data(), sizeof(draw));
            CAPTURE(draw.instanceCount);
            CHECK(draw.instanceCount >= 1);
            CHECK(draw.instanceCount < 9);
            total += draw.instanceCount;
        }
        CHECK(total < 27);
    }
}

TEST_CASE("grass.lod: with MSAA, where nothing is drawn the frame shows the scene's background") {
    // Its multisampled target is cleared in the first band's pass and resolved in the last: the
    // clear must be the background, as in grass.geometry's single pass.
    Scene scene = lod_field_scene();
    scene.background = glm::vec3(0.45f, 0.6f, 0.85f);
    Values values = lod_values(1.5, 2.5, 3.0, 4.0);
    values["samples"] = 4LL;
    values["coverage"] = std::string("alpha_to_coverage");
    for (const bool lod : {true, false}) {
        CAPTURE(lod);
        const Image image = lod ? render(scene, "grass.lod", values) : render(scene, "grass.geometry", {{"samples", 4LL}});
        const float* sky = image.at(80, 1);  // the top row looks 16 degrees above the horizon
        for (int c = 0; c < 3; ++c) CHECK(sky[c] == doctest::Approx(scene.background[c]).epsilon(1e-3));
    }
}

TEST_CASE("grass.lod: the middle band ray-cast per sample under 4x MSAA is closer to the reference than once per pixel") {
    // Cells 9-14 m away at 160 x 96: the volume's texels are smaller than a pixel, and a walk once
    // per pixel picks one of them for all four samples (measured: RMSE 0.0100 per pixel, 0.0054 per
    // sample; with the pipeline's sample shading but no `sample` qualifier, both 0.0100). The bands
    // keep every cell in the volume.
    Scene scene = lod_field_scene();
    scene.camera.position = glm::vec3(1.5f, 1.2f, 12.0f);
    scene.camera.target = glm::vec3(1.5f, 0.0f, 1.5f);
    ReferenceSettings settings;
    settings.pixel_samples = 16;
    settings.light_samples = 1;
    const Image truth = render_reference(scene, build_scene_meshes(scene), 160, 96, settings).radiance;
    const auto rmse = [&](const Image& image) {
        double sum = 0.0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    REQUIRE(std::isfinite(image.at(x, y)[c]));
                    const double d = double(image.at(x, y)[c]) - double(truth.at(x, y)[c]);
                    sum += d * d;
                }
        return std::sqrt(sum / (3.0 * image.width * image.height));
    };
    Values values = lod_values(0.0, 0.0, 1e5, 1e5);
    values["samples"] = 4LL;
    for (const char* culling : {"gpu", "quadtree"}) {  // the per-cell walk and the macro-cells' walk
        CAPTURE(culling);
        values["culling"] = std::string(culling);
        values["middle_per_sample"] = false;
        const Image per_pixel = render(scene, "grass.lod", values);
        values["middle_per_sample"] = true;
        const Image per_sample = render(scene, "grass.lod", values);
        const double once = rmse(per_pixel), each = rmse(per_sample);
        MESSAGE(std::string(culling) << ": RMSE against the reference: once per pixel " << once << ", per sample " << each);
        CHECK(max_difference(per_pixel, per_sample) > 0.05f);
        CHECK(each < 0.9 * once);
    }

    // Only for the volume under 4x MSAA.
    const Technique& t = *TechniqueRegistry::instance().find("grass.lod");
    Values one = lod_values(0.0, 0.0, 1e5, 1e5);
    one["middle_per_sample"] = true;
    CHECK(t.conflict(ParamSet::resolve(t.params(), one, {}, {}, "grass.lod")));
    values["culling"] = std::string("gpu");
    values["middle"] = std::string("slices");
    CHECK(t.conflict(ParamSet::resolve(t.params(), values, {}, {}, "grass.lod")));
}

TEST_CASE("grass.lod on a terrain: each band alone draws what its representation draws on the hills, and the GPU "
          "culls change no pixel") {
    // The hills' 4 x 4 cells lie 2-8 m from the standing eye, rising 1.2 m.
    const Scene hills = grass::test::hills_scene("[camera]\nposition = [0.0, 2.5, 4.5]\ntarget = [0.0, 0.3, 0.0]\nfov = 45", 1.2);
    const Image blades = render(hills, "grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}});
    const Image volume = render(hills, "grass.volume", {{"slices", 4LL}, {"resolution", 96LL}, {"height_resolution", 48LL}});
    const Image slices = render(hills, "grass.slices",
                                {{"slices", 4LL}, {"resolution", 96LL}, {"height_resolution", 48LL}, {"mip_filter", std::string("coverage")}});
    const Image image = render(hills, "grass.image", {{"resolution", 128LL}});
    CHECK(max_difference(blades, volume) > 0.1f);
    CHECK(max_difference(volume, slices) > 0.1f);
    CHECK(max_difference(blades, image) > 0.1f);
    for (const std::string culling : {"none", "gpu"}) {
        CAPTURE(culling);
        for (const std::string middle : {"volume", "slices"}) {
            CAPTURE(middle);
            const auto lod = [&](double a, double b, double c, double d) {
                Values values = lod_values(a, b, c, d);
                values["culling"] = culling;
                values["middle"] = middle;
                return render(hills, "grass.lod", values);
            };
            CHECK(max_difference(lod(1e6, 1e6, 1e6, 1e6), blades) <= 1e-5f);
            CHECK(max_difference(lod(0, 0, 1e6, 1e6), middle == "volume" ? volume : slices) <= 1e-5f);
            CHECK(max_difference(lod(0, 0, 0, 0), image) <= 1e-5f);
            // Every band drawing some cells: the culls keep what each band draws.
            if (culling == "gpu") {
                Values values = lod_values(3.0, 4.0, 5.0, 6.0);
                values["middle"] = middle;
                values["culling"] = std::string("none");
                const Image whole = render(hills, "grass.lod", values);
                values["culling"] = std::string("gpu");
                CHECK(max_difference(render(hills, "grass.lod", values), whole) <= 1e-5f);
                CHECK(max_difference(whole, blades) > 0.1f);
            }
        }
    }
}

TEST_CASE("grass.lod's volume levels (Lemme's 8, 2 and 1 slices): each level alone draws what grass.volume draws with "
          "its slices, and every culling keeps what each level draws") {
    const Scene scene = lod_field_scene();
    const Technique& lod = *TechniqueRegistry::instance().find("grass.lod");
    const auto lod_levels = [&](double v2, double v3, const std::string& culling) {
        // No blades, no image: level 1 to v2, level 2 to v3, level 3 beyond (steps).
        Values values = lod_values(0, 0, 1e6, 1e6);
        values["volume_levels"] = 3LL;
        values["slices_2"] = 2LL;
        values["slices_3"] = 1LL;
        values["volume_2_start"] = v2;
        values["volume_2_full"] = v2;
        values["volume_3_start"] = v3;
        values["volume_3_full"] = v3;
        values["culling"] = culling;
        values["middle_macro_max"] = 2LL;
        return values;
    };
    for (const std::string culling : {"none", "gpu", "quadtree"}) {
        CAPTURE(culling);
        const Values volume_macro = culling == "quadtree" ? Values{{"macro_cells", 2LL}} : Values{};
        const auto volume = [&](long long slices) {
            Values values = volume_macro;
            values.insert({{"slices", slices}, {"resolution", 96LL}, {"height_resolution", 48LL}});
            return render(scene, "grass.volume", values);
        };
        const Image level1 = volume(4), level2 = volume(2), level3 = volume(1);
        CHECK(max_difference(level1, level2) > 0.1f);
        CHECK(max_difference(level2, level3) > 0.1f);
        CHECK(max_difference(render(scene, "grass.lod", lod_levels(1e6, 1e6, culling)), level1) <= 1e-5f);
        CHECK(max_difference(render(scene, "grass.lod", lod_levels(0, 1e6, culling)), level2) <= 1e-5f);
        CHECK(max_difference(render(scene, "grass.lod", lod_levels(0, 0, culling)), level3) <= 1e-5f);
    }
    // The cells (1-5 m away) in all three levels: the GPU culls change no pixel.
    Values split = lod_levels(0, 0, "none");
    split["volume_2_start"] = 2.0;
    split["volume_2_full"] = 2.6;
    split["volume_3_start"] = 3.0;
    split["volume_3_full"] = 3.4;
    const Image whole = render(scene, "grass.lod", split);
    split["culling"] = std::string("gpu");
    CHECK(max_difference(render(scene, "grass.lod", split), whole) <= 1e-5f);
    CHECK(max_difference(whole, render(scene, "grass.lod", lod_levels(1e6, 1e6, "none"))) > 0.1f);
    // Levels are the volume's: refused with the BTF slices, and out-of-order distances are refused.
    Values btf = lod_levels(1e6, 1e6, "none");
    btf["middle"] = std::string("slices");
    CHECK(lod.conflict(ParamSet::resolve(lod.params(), btf, {}, {}, "grass.lod")));
    Values disordered = lod_levels(0, 0, "none");
    disordered["volume_3_start"] = 5.0;  // beyond volume_3_full (0)
    const auto conflict = lod.conflict(ParamSet::resolve(lod.params(), disordered, {}, {}, "grass.lod"));
    REQUIRE(conflict);
    CHECK(conflict->hint.find("volume_3_start <= volume_3_full <= image_start") != std::string::npos);
    CHECK(conflict->message.find("volume_3_start = 5") != std::string::npos);
}
