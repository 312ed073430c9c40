// grass.lod with culling = "quadtree" (Lemme §6.1-6.2: a CPU traversal every frame, the middle and
// far bands as macro-cells): with its bands pushed to either end it draws what grass.geometry,
// grass.volume and grass.image (the last two with macro-cells of the same size) draw alone; across
// a field in all three bands it covers as the representations do; its counts are the draws it
// records; the field's copies stay on the CPU; and a frame that needs more near cells than it may
// hold, or a scene with two grass populations, fails saying what to change.
#include "support/bake_truth.hpp"
#include "support/cpu_checks.hpp"
#include "support/lod_field.hpp"

#include "config/population_overrides.hpp"
#include "config/scene_config.hpp"
#include "core/error.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "scene/population.hpp"
#include "support/test_gpu.hpp"
#include "../shaders/lod_selection.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>

using namespace canopy;
using grass::test::lod_field_scene;
using grass::test::max_difference;

namespace {

using Values = std::map<std::string, ParamValue>;

const Technique& technique(const std::string& name) {
    const Technique* t = TechniqueRegistry::instance().find(name);
    REQUIRE(t);
    return *t;
}

std::unique_ptr<FrameRenderer> renderer(const Scene& scene, const std::string& name, const Values& values) {
    const Technique& t = technique(name);
    return std::make_unique<FrameRenderer>(test::gpu(), scene, build_scene_meshes(scene), 160, 96,
                                           t.graph(ParamSet::resolve(t.params(), values, {}, {}, name)));
}

Image render(const Scene& scene, const std::string& name, const Values& values) {
    auto r = renderer(scene, name, values);
    r->render();
    return r->read_color();
}

Values quadtree_values(double geometry_full, double geometry_none, double image_start, double image_full,
                       const char* mip_filter = "coverage") {
    return {{"geometry_full", geometry_full}, {"geometry_none", geometry_none}, {"image_start", image_start},
            {"image_full", image_full},       {"samples", 1LL},                 {"coverage", std::string("alpha_test")},
            {"slices", 4LL},                  {"resolution", 96LL},             {"height_resolution", 48LL},
            {"image_resolution", 128LL},      {"culling", std::string("quadtree")},
            {"middle_macro_max", 2LL},        {"far_macro_max", 2LL},          {"mip_filter", std::string(mip_filter)},
            {"bake_supersampling", std::string(mip_filter) == "none" ? 1LL : 2LL}};
}

double counter(const FrameTiming& t, const std::string& name) {
    for (const auto& [n, v] : t.counters)
        if (n == name) return v;
    FAIL("no counter " << name);
    return 0;
}

template <typename T>
T read_record(FrameRenderer& r, const std::string& buffer) {
    const std::vector<std::byte> bytes = r.read_buffer(buffer);
    REQUIRE(bytes.size() >= sizeof(T));
    T record;
    std::memcpy(&record, bytes.data(), sizeof(T));
    return record;
}

}  // namespace

TEST_CASE("grass.lod quadtree: with its bands at either end it draws what each representation draws alone") {
    const Scene scene = lod_field_scene();
    // The quadtree's nodes of at most 2 cells a side over 3 x 3 cells are grass.volume's and
    // grass.image's macro-cells of 2: (0, 0) 2 x 2, (2, 0) 1 x 2, (0, 2) 2 x 1, (2, 2) 1 x 1.
    const Image blades = render(scene, "grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}});
    const Image volume = render(scene, "grass.volume",
                                {{"slices", 4LL}, {"resolution", 96LL}, {"height_resolution", 48LL}, {"macro_cells", 2LL}});
    const Image image = render(scene, "grass.image", {{"resolution", 128LL}, {"macro_cells", 2LL}});
    CHECK(grass::test::grass_pixels(blades) > 1000);
    CHECK(grass::test::grass_pixels(volume) > 1000);
    CHECK(grass::test::grass_pixels(image) > 400);
    CHECK(max_difference(render(scene, "grass.lod", quadtree_values(1e6, 1e6, 1e6, 1e6)), blades) <= 1e-5f);
    CHECK(max_difference(render(scene, "grass.lod", quadtree_values(0, 0, 1e6, 1e6)), volume) <= 1e-5f);
    CHECK(max_difference(render(scene, "grass.lod", quadtree_values(0, 0, 0, 0)), image) <= 1e-5f);
}

TEST_CASE("grass.lod quadtree: a macro-cell's volume and image each draw only their own band of its cell's blades") {
    // One cell seen from 80 m, 10 degrees off the vertical (rays straight down would run along the
    // volume's slices), its centre where the image's ramp (0 to 160 m) is one half: no blades, the
    // volume keeps thresholds in (0, 0.5], the image (0.5, 1]. So each pixel must show the nearer
    // of the volume at density 0.5 and the image's texel where its blade's threshold is above 0.5
    // (shown at density 1, not at 0.5), or nothing. A band that draws the other's blades breaks that.
    const char* tilted =
        "[camera]\nposition = [0.5, 78.784620, 14.391854]\ntarget = [0.5, 0, 0.5]\nup = [0, 0, -1]\nfov = 0.9\n"
        "near = 40\nfar = 120";
    const Scene full = grass::test::one_cell_scene(tilted, "density = 1.0");
    const Scene half = grass::test::one_cell_scene(tilted, "density = 0.5");
    // Level 0 alone (mip_filter = "none"), where a texel is one blade: filtered texels are shares
    // of blades, which the bands split by blade_texel_share (test_lod_selection checks it adds up).
    const Values volume_values{{"slices", 4LL},       {"resolution", 96LL},
                               {"height_resolution", 48LL},          {"macro_cells", 1LL},
                               {"mip_filter", std::string("none")}, {"bake_supersampling", 1LL}};
    const Values image_values{
        {"resolution", 128LL}, {"macro_cells", 1LL}, {"mip_filter", std::string("none")}, {"bake_supersampling", 1LL}};
    const auto shown = [](const Scene& scene, const std::string& name, const Values& values) {
        auto r = renderer(scene, name, values);
        r->render();
        return r->read_color_and_pixel_visibility();  // visibility: G = view depth, A = drawn
    };
    const auto volume_half = shown(half, "grass.volume", volume_values);
    const auto image_half = shown(half, "grass.image", image_values);
    const auto image_full = shown(full, "grass.image", image_values);
    Values binary = quadtree_values(0, 0, 0, 160, "none");
    binary["transition"] = std::string("binary");
    const auto lod = shown(full, "grass.lod", binary);
    int from_volume = 0, from_image = 0, wrong = 0;
    for (int y = 0; y < lod.color.height; ++y)
        for (int x = 0; x < lod.color.width; ++x) {
            const float* expected = nullptr;
            float depth = 1e30f;
            if (grass::test::shows_grass(volume_half.color.at(x, y))) {
                expected = volume_half.color.at(x, y);
                depth = volume_half.visibility.at(x, y)[1];
            }
            const bool image_band = grass::test::shows_grass(image_full.color.at(x, y)) &&
                                    !grass::test::shows_grass(image_half.color.at(x, y));
            if (image_band && image_full.visibility.at(x, y)[1] < depth) expected = image_full.color.at(x, y);
            if (expected) (expected == volume_half.color.at(x, y) ? from_volume : from_image)++;
            const float* got = lod.color.at(x, y);
            if (!expected) {
                wrong += grass::test::shows_grass(got);
                continue;
            }
            for (int c = 0; c < 3; ++c) wrong += std::abs(got[c] - expected[c]) > 1e-5f;
        }
    CAPTURE(from_volume);
    CAPTURE(from_image);
    CHECK(from_volume > 150);
    CHECK(from_image > 100);
    CHECK(wrong == 0);
}

TEST_CASE("grass.lod quadtree: a cut through a cell splits its blades by their roots' distance, not the cell's centre's") {
    // The one cell of the tests above, the blades handing over to the image in a step at the
    // distance of the cell's centre: cut per blade (the default), the roots nearer than that
    // stay blades and the farther ones go to the image, so the frame shows both; cut at the
    // centre (transition_distance = "cell", or a shader taking the centre for the root), the
    // whole cell goes one way.
    const char* tilted =
        "[camera]\nposition = [0.5, 78.784620, 14.391854]\ntarget = [0.5, 0, 0.5]\nup = [0, 0, -1]\nfov = 0.9\n"
        "near = 40\nfar = 120";
    const Scene full = grass::test::one_cell_scene(tilted, "density = 1.0");
    const double centre = glm::distance(glm::vec3(0.5f, 78.784620f, 14.391854f), glm::vec3(0.5f, 0.0f, 0.5f));
    const auto frame = [&](double step, const std::string& distance) {
        Values values = quadtree_values(step, step, step, step, "none");
        values["transition"] = std::string("binary");
        values["transition_distance"] = distance;
        return render(full, "grass.lod", values);
    };
    const Image blades = frame(1e6, "blade"), image = frame(0.0, "blade");
    for (const std::string distance : {"blade", "cell"}) {
        CAPTURE(distance);
        const Image split = frame(centre, distance);
        int as_blades = 0, as_image = 0;
        for (int y = 0; y < split.height; ++y)
            for (int x = 0; x < split.width; ++x) {
                const float *b = blades.at(x, y), *i = image.at(x, y), *got = split.at(x, y);
                const auto same = [](const float* p, const float* q) {
                    return std::abs(p[0] - q[0]) <= 1e-5f && std::abs(p[1] - q[1]) <= 1e-5f && std::abs(p[2] - q[2]) <= 1e-5f;
                };
                if (same(b, i)) continue;  // where the two agree, the split says nothing
                as_blades += grass::test::shows_grass(b) && same(got, b);
                as_image += grass::test::shows_grass(i) && same(got, i);
            }
        MESSAGE(distance << ": " << as_blades << " pixels as the blades, " << as_image << " as the image");
        if (distance == "blade") {
            CHECK(as_blades > 300);
            CHECK(as_image > 300);
        } else {
            CHECK(std::min(as_blades, as_image) < 30);
        }
    }
}

TEST_CASE("grass.lod quadtree: across a smooth transition window each pixel shows the binary cut at its screen-door "
          "value's threshold (the two bands share the window's blades on complementary pixels)") {
    // The cell of the test above, one cut at 0.4 taken at the cell's centre (transition_distance =
    // "cell", so every blade has the same cut): the blades against the volume (near/middle), or the
    // volume against the image (middle/far). A window of width 0.25 around it: the nearer band
    // draws a blade at x = bdth / ld on the pixels whose screen-door value h lies below
    // 1 - beyond(x), the farther on the others; so at pixel p the frame is the binary cut at
    // x_v(h(p)), the threshold where beyond(x) reaches 1 - h. Binary frames at 17 cuts across the
    // window bracket every pixel's x_v; where the two bracketing frames agree, the smooth frame
    // must show what they show. A window taken at 1 - c instead of c, one that drops or doubles
    // the window's blades, or a screen door that differs between the bands breaks it.
    const char* tilted =
        "[camera]\nposition = [0.5, 78.784620, 14.391854]\ntarget = [0.5, 0, 0.5]\nup = [0, 0, -1]\nfov = 0.9\n"
        "near = 40\nfar = 120";
    const Scene full = grass::test::one_cell_scene(tilted, "density = 1.0");
    const double centre = glm::distance(glm::vec3(0.5f, 78.784620f, 14.391854f), glm::vec3(0.5f, 0.0f, 0.5f));
    constexpr float kCut = 0.4f, kWidth = 0.25f;
    constexpr int kCuts = 16;
    for (const bool near_middle : {true, false}) {
        CAPTURE(near_middle);
        const auto frame = [&](double cut, const std::string& transition) {
            // The blades' ramp from 0 to geometry_none is cut at the cell's centre, or the image's
            // ramp from 0 to image_full is 1 - cut there.
            Values values = near_middle ? quadtree_values(0, centre / (1.0 - cut), 1e6, 1e6, "none")
                                        : quadtree_values(0, 0, 0, centre / (1.0 - cut), "none");
            values["transition_distance"] = std::string("cell");
            values["transition"] = transition;
            values["transition_width"] = double(kWidth);
            return render(full, "grass.lod", values);
        };
        for (const auto& [transition, window] : {std::pair{"lemme", canopy::shader::GRASS_LOD_WINDOW_SMOOTHSTEP},
                                                 std::pair{"boulanger", canopy::shader::GRASS_LOD_WINDOW_LINEAR}}) {
            CAPTURE(transition);
            const float half = canopy::shader::lod_window_half_width(kCut, window, kWidth);
            const float top = canopy::shader::lod_window_top(kCut, half), bottom = top - 2.0f * half;
            std::vector<Image> cuts;
            for (int k = 0; k <= kCuts; ++k) cuts.push_back(frame(bottom + (top - bottom) * double(k) / kCuts, "binary"));
            const Image smooth = frame(kCut, transition);
            int checked = 0, wrong = 0, in_window = 0;
            for (int y = 0; y < smooth.height; ++y)
                for (int x = 0; x < smooth.width; ++x) {
                    const float h = canopy::shader::lod_screen_door(glm::vec2(float(x), float(y)));
                    // x_v: the largest threshold the nearer band still draws at this pixel, by bisection.
                    float lo = 0.0f, hi = 1.0f;
                    for (int i = 0; i < 40; ++i) {
                        const float mid = 0.5f * (lo + hi);
                        (canopy::shader::lod_beyond(mid, kCut, window, kWidth) < 1.0f - h ? lo : hi) = mid;
                    }
                    const int k = std::clamp(int(std::floor((lo - bottom) / (top - bottom) * kCuts)), 0, kCuts - 1);
                    const float* a = cuts[size_t(k)].at(x, y);
                    const float* b = cuts[size_t(k + 1)].at(x, y);
                    if (std::abs(a[0] - b[0]) > 1e-5f || std::abs(a[1] - b[1]) > 1e-5f || std::abs(a[2] - b[2]) > 1e-5f) continue;
                    ++checked;
                    // A pixel whose frame the cut changes within the window: the window's blades.
                    const float* first = cuts.front().at(x, y);
                    const float* last = cuts.back().at(x, y);
                    in_window += std::abs(first[0] - last[0]) + std::abs(first[1] - last[1]) + std::abs(first[2] - last[2]) > 1e-4f;
                    const float* got = smooth.at(x, y);
                    for (int c = 0; c < 3; ++c) wrong += std::abs(got[c] - a[c]) > 1e-5f;
                }
            MESSAGE(std::string(near_middle ? "near/middle " : "middle/far ") << std::string(transition) << ": " << checked
                                                                  << " pixels checked, " << in_window << " in the window, "
                                                                  << wrong << " wrong");
            CHECK(checked > smooth.width * smooth.height / 2);
            CHECK(in_window > 300);
            CHECK(wrong == 0);
        }
    }
}

TEST_CASE("grass.lod quadtree: a field in all three bands covers as the representations do, counting its draws") {
    const Scene scene = lod_field_scene();
    // Each cell's band at its centre (transition_distance = "cell"), so the counts below are of
    // cells whose centre lies in each band.
    Values values = quadtree_values(2.0, 2.6, 3.0, 3.4);
    values["transition_distance"] = std::string("cell");
    auto r = renderer(scene, "grass.lod", values);
    const FrameTiming t = r->render();
    const Image lod = r->read_color();
    for (float v : lod.pixels) REQUIRE(std::isfinite(v));
    // The counts are what the CPU pass wrote into the draws' records.
    const auto near_draw = read_record<VkDrawIndexedIndirectCommand>(*r, "near_quadtree_draw");
    const auto middle_draw = read_record<VkDrawIndirectCommand>(*r, "middle_quadtree_draw");
    const auto far_draw = read_record<VkDrawIndirectCommand>(*r, "far_quadtree_draw");
    CHECK(counter(t, "near_draws") == near_draw.instanceCount);
    CHECK(counter(t, "near_cells") == near_draw.instanceCount);
    CHECK(counter(t, "middle_draws") == middle_draw.instanceCount);
    CHECK(counter(t, "far_draws") == far_draw.instanceCount);
    CHECK(middle_draw.vertexCount == 36);
    CHECK(far_draw.vertexCount == 6);
    // Every band draws some cells and none all 9 (the first row is too near for the image, the
    // last too far for the blades and the middle band); the nodes tested are few.
    for (const char* band : {"near_cells", "middle_cells", "far_cells"}) {
        CAPTURE(band);
        CHECK(counter(t, band) >= 1);
        CHECK(counter(t, band) < 9);
    }
    CHECK(counter(t, "quadtree_nodes") <= 1 + 4 + 9);
    CHECK(t.uploaded_bytes > 0);
    // Taken at each blade's root (the default), a band keeps every cell a root of which may lie
    // in it (QuadtreeBand::root_margin): at least the cells whose centre does. Without the margin
    // it keeps the same cells, and the blades rooted across a band's edge go missing.
    {
        Values by_root = values;
        by_root["transition_distance"] = std::string("blade");
        auto rb = renderer(scene, "grass.lod", by_root);
        const FrameTiming tb = rb->render();
        int more = 0;
        for (const char* band : {"near_cells", "middle_cells", "far_cells"}) {
            CAPTURE(band);
            CHECK(counter(tb, band) >= counter(t, band));
            more += counter(tb, band) > counter(t, band);
        }
        CHECK(more >= 1);
    }

    const Image blades = render(scene, "grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}});
    const Image image = render(scene, "grass.image", {{"resolution", 128LL}});
    const auto lod_agreement = grass::test::compare_with_reference_hits(scene, lod);
    const auto blades_agreement = grass::test::compare_with_reference_hits(scene, blades);
    const auto image_agreement = grass::test::compare_with_reference_hits(scene, image);
    CAPTURE(lod_agreement.differ);
    CAPTURE(blades_agreement.differ);
    CAPTURE(image_agreement.differ);
    CHECK(lod_agreement.covered > 150);
    CHECK(lod_agreement.differ <= std::max(blades_agreement.differ, image_agreement.differ) + lod_agreement.compared / 50);
    CHECK(max_difference(lod, blades) > 0.1f);
    CHECK(max_difference(lod, image) > 0.1f);
}

TEST_CASE("grass.lod quadtree: the field's copies stay on the CPU") {
    const Scene scene = lod_field_scene();
    Values values = quadtree_values(2.0, 2.6, 3.0, 3.4);
    const uint64_t quadtree_scene = renderer(scene, "grass.lod", values)->memory().scene_bytes;
    values["culling"] = std::string("gpu");
    values.erase("middle_macro_max");
    values.erase("far_macro_max");
    const uint64_t gpu_scene = renderer(scene, "grass.lod", values)->memory().scene_bytes;
    CHECK(gpu_scene - quadtree_scene == 9 * sizeof(PopulationInstance));
}

TEST_CASE("grass.lod quadtree: a field costs 32 bytes of GPU memory a cell, whatever its size") {
    // GrassCell (32 bytes) per cell; the bands' lists are sized by near_capacity and
    // macro_capacity, not by the field; the copies (128 bytes) stay on the CPU. `canopy bench
    // grass-scale` reports the same slope.
    const auto gpu_bytes = [](uint32_t side) {
        Scene scene = lod_field_scene();
        override_population_params(scene.populations.at(0), {{"cells_x", (long long)side}, {"cells_z", (long long)side}},
                                   {}, {});
        const MemoryUse m = renderer(scene, "grass.lod", quadtree_values(2.0, 2.6, 3.0, 3.4))->memory();
        return m.technique_bytes + m.scene_bytes;
    };
    CHECK(gpu_bytes(6) - gpu_bytes(3) == (36 - 9) * 32);
    CHECK(gpu_bytes(20) - gpu_bytes(3) == (400 - 9) * 32);
    // On a terrain, 4 more: the grid heights.
    const auto terrain_bytes = [](uint32_t side) {
        const Scene scene = parse_scene(
            fmt::format("[scene]\nname = \"hills\"\n[camera]\nposition = [0, 3, 4]\ntarget = [0, 0, 0]\n"
                        "[[light]]\ntype = \"directional\"\ndirection = [-0.3, -1, -0.2]\n"
                        "[[object]]\nname = \"ground\"\nshape = \"heightfield\"\nsize = [{0}, {0}]\nvertices = {1}\n"
                        "periods = 1\nseed = 2\nheight_scale = 1\n"
                        "[[population]]\nname = \"field\"\nkind = \"grass\"\nterrain = \"ground\"\n"
                        "params = {{ cells_x = {0}, cells_z = {0}, blades = 60, subdivisions = 3 }}\n",
                        side, side + 1),
            "hills.toml");
        // The technique's alone: the scene's ground mesh grows with the field too.
        return renderer(scene, "grass.lod", quadtree_values(2.0, 2.6, 3.0, 3.4))->memory().technique_bytes;
    };
    CHECK(terrain_bytes(20) - terrain_bytes(3) == (400 - 9) * 36);
}

TEST_CASE("grass.lod quadtree: more near cells than near_capacity, more macro-cells than macro_capacity, or two grass "
          "populations, fail the frame saying what to change") {
    {
        Values values = quadtree_values(1e6, 1e6, 1e6, 1e6);
        values["near_capacity"] = 4LL;
        auto r = renderer(lod_field_scene(), "grass.lod", values);
        CHECK_THROWS_WITH_AS(r->render(), doctest::Contains("raise near_capacity"), GpuError);
    }
    {
        // All image: the 3 x 3 cells as macro-cells of at most 2 a side are 4 draws.
        Values values = quadtree_values(0, 0, 0, 0);
        values["macro_capacity"] = 4LL;
        CHECK_NOTHROW(renderer(lod_field_scene(), "grass.lod", values)->render());
        values["macro_capacity"] = 3LL;
        auto r = renderer(lod_field_scene(), "grass.lod", values);
        CHECK_THROWS_WITH_AS(r->render(), doctest::Contains("the far band keeps 4 macro-cells this frame, more than macro_capacity = 3: raise macro_capacity"), GpuError);
    }
    {
        const Scene two = lod_field_scene(R"([[population]]
name = "more_grass"
kind = "grass"
albedo = [0.1, 0.8, 0.1]
params = { cells_x = 2, cells_z = 2, blades = 10 }
)");
        auto r = renderer(two, "grass.lod", quadtree_values(2.0, 2.6, 3.0, 3.4));
        CHECK_THROWS_WITH_AS(r->render(), doctest::Contains("one grass population"), GpuError);
    }
}

TEST_CASE("grass.lod quadtree: the BTF slices have no macro-cells, so middle = slices is refused with it") {
    const Technique& t = technique("grass.lod");
    Values values = quadtree_values(2.0, 2.6, 3.0, 3.4);
    values["middle"] = std::string("slices");
    const auto conflict = t.conflict(ParamSet::resolve(t.params(), values, {}, {}, "grass.lod"));
    REQUIRE(conflict);
    CHECK(conflict->hint.find("middle = \"volume\"") != std::string::npos);
}

TEST_CASE("grass.lod: the hilltops are the quadtree's lod test, so hilltop_volume is refused without it") {
    const Technique& t = technique("grass.lod");
    for (const char* culling : {"gpu", "none"}) {
        CAPTURE(culling);
        Values values = quadtree_values(2.0, 2.6, 3.0, 3.4);
        values["culling"] = std::string(culling);
        values["hilltop_volume"] = true;
        const auto conflict = t.conflict(ParamSet::resolve(t.params(), values, {}, {}, "grass.lod"));
        REQUIRE(conflict);
        CHECK(conflict->hint.find("culling = \"quadtree\"") != std::string::npos);
        values["culling"] = std::string("quadtree");
        CHECK(!t.conflict(ParamSet::resolve(t.params(), values, {}, {}, "grass.lod")));
    }
}

TEST_CASE("grass.lod quadtree on a terrain: with its bands at either end it draws what each representation draws "
          "alone on the hills") {
    // The hills' 4 x 4 cells: the quadtree's nodes of at most 2 cells a side are the macro-cells
    // of 2, and the image's splits where the ground is uneven are the same in both (a 2 x 2 node
    // into its four cells).
    const Scene hills = grass::test::hills_scene("[camera]\nposition = [0.0, 2.5, 4.5]\ntarget = [0.0, 0.3, 0.0]\nfov = 45", 1.2);
    const Image blades = render(hills, "grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}});
    const Image volume = render(hills, "grass.volume",
                                {{"slices", 4LL}, {"resolution", 96LL}, {"height_resolution", 48LL}, {"macro_cells", 2LL}});
    CHECK(max_difference(render(hills, "grass.lod", quadtree_values(1e6, 1e6, 1e6, 1e6)), blades) <= 1e-5f);
    CHECK(max_difference(render(hills, "grass.lod", quadtree_values(0, 0, 1e6, 1e6)), volume) <= 1e-5f);
    for (const double unplanarity : {0.05, 1e4}) {
        CAPTURE(unplanarity);
        const Image image =
            render(hills, "grass.image", {{"resolution", 128LL}, {"macro_cells", 2LL}, {"macro_unplanarity", unplanarity}});
        Values values = quadtree_values(0, 0, 0, 0);
        values["macro_unplanarity"] = unplanarity;
        CHECK(max_difference(render(hills, "grass.lod", values), image) <= 1e-5f);
    }
    // The two image checks above tell the splits apart.
    CHECK(max_difference(render(hills, "grass.image", {{"resolution", 128LL}, {"macro_cells", 2LL}}),
                         render(hills, "grass.image", {{"resolution", 128LL}, {"macro_cells", 2LL}, {"macro_unplanarity", 1e4}})) >
          0.1f);
}

TEST_CASE("grass.lod quadtree on a terrain: the macro-cells' bands take a cell's distance where its copy's blades do, "
          "at its first corner's ground") {
    // One cell on a slope, the eye 2 m above its first corner's ground and 1 m aside. With every
    // band's edge at `cut`, between the eye's distance to the cell's centre lifted to that ground
    // and to the centre on the field's plane, the cell is all blades: the middle and far bands,
    // drawn as macro-cells, must draw nothing of it, as the blades' copies see it.
    const std::string ground = "[[object]]\nname = \"ground\"\nshape = \"heightfield\"\nsize = [1, 1]\nvertices = 2\n"
                               "periods = 1\nseed = 7\nheight_scale = 3\nalbedo = [0.6, 0.3, 0.1]\n";
    const auto scene_with = [&](const std::string& camera) {
        return parse_scene(std::string("[scene]\nname = \"slope\"\nambient = 0.2\n") + camera +
                               "\n[[light]]\ntype = \"directional\"\ndirection = [-0.3, -1, -0.2]\ncasts_shadows = false\n" +
                               ground +
                               "[[population]]\nname = \"field\"\nkind = \"grass\"\nterrain = \"ground\"\n"
                               "albedo = [0.1, 0.8, 0.1]\nparams = { cells_x = 1, cells_z = 1, blades = 300, subdivisions = 3 }\n",
                           "slope.toml");
    };
    const Scene probe = scene_with("[camera]\nposition = [0, 5, 3]\ntarget = [0, 0, 0]");
    const PopulationInstance copy = generate_instances(probe.populations.at(0))->at(0);
    const glm::vec3 lifted = glm::vec3(copy.model * glm::vec4(0.5f, 0.0f, 0.5f, 1.0f));
    const float ground_height = copy.model[3].y;
    CAPTURE(ground_height);
    REQUIRE(ground_height > 0.6f);  // the seed's slope lifts the first corner well above the plane
    const glm::vec3 eye = lifted + glm::vec3(0.0f, 2.0f, 1.0f);
    const glm::vec3 on_plane(lifted.x, lifted.y - ground_height, lifted.z);
    const double cut = 0.5 * (glm::length(eye - lifted) + glm::length(eye - on_plane));
    const Scene scene = scene_with(fmt::format("[camera]\nposition = [{}, {}, {}]\ntarget = [{}, {}, {}]\nfov = 60",
                                               eye.x, eye.y, eye.z, lifted.x, lifted.y, lifted.z));
    const Image blades = render(scene, "grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}});
    CHECK(grass::test::grass_pixels(blades) > 250);
    // Blades to `cut`, then the volume (left) or the image (right).
    CHECK(max_difference(render(scene, "grass.lod", quadtree_values(cut, cut, 1e6, 1e6)), blades) <= 1e-5f);
    CHECK(max_difference(render(scene, "grass.lod", quadtree_values(cut, cut, cut, cut)), blades) <= 1e-5f);
    // Past `cut` the cell is the other bands' alone: the check above sees a band that draws it.
    const double beyond = glm::length(eye - lifted) - 0.2;
    CHECK(max_difference(render(scene, "grass.lod", quadtree_values(beyond, beyond, 1e6, 1e6)), blades) > 0.1f);
}

TEST_CASE("grass.lod quadtree: Lemme's hilltops (§6.4.6) draw the far band's blades again where a cell reaches above "
          "the eye, and nothing seen from above") {
    // The hills' 4 x 4 cells all in the far band (the image's), seen from low across the crests.
    const Scene low = grass::test::hills_scene("[camera]\nposition = [0.0, 0.25, 4.5]\ntarget = [0.0, 0.6, 0.0]\nfov = 45", 1.2);
    const Scene high = grass::test::hills_scene("[camera]\nposition = [0.0, 6.0, 3.0]\ntarget = [0.0, 0.3, 0.0]\nfov = 45", 1.2);
    // Level 0 alone (mip_filter = "none"): the image's flatness is what the hilltops answer. Filtered
    // as by default, the image's quads alone come nearer the reference at this low view (0.020),
    // and the hilltop volume, met at grazing angles, takes coarse levels and over-covers the crests
    // (0.059; anisotropic lookups: 0.038 against 0.029): `lod/README.md`.
    Values plain = quadtree_values(0, 0, 0, 0, "none");
    Values hilltops = plain;
    hilltops["hilltop_volume"] = true;
    const auto frame = [&](const Scene& scene, const Values& values) {
        auto r = renderer(scene, "grass.lod", values);
        const FrameTiming t = r->render();
        return std::make_pair(t, r->read_color());
    };
    const auto [low_timing, low_image] = frame(low, hilltops);
    const auto [low_plain_timing, low_plain] = frame(low, plain);
    for (float v : low_image.pixels) REQUIRE(std::isfinite(v));
    CAPTURE(counter(low_timing, "hilltop_cells"));
    CAPTURE(counter(low_timing, "far_cells"));
    CHECK(counter(low_timing, "hilltop_cells") >= 1);
    CHECK(counter(low_timing, "hilltop_cells") <= counter(low_timing, "far_cells"));
    CHECK(max_difference(low_image, low_plain) > 0.1f);
    // Seen from across, the image's quads lie flat on the hills: the crests' outline is bare
    // ground against the sky (Lemme's "undesired flatness"). The blades standing above it come
    // back with the volume's slices: per 8 x 8 tile, the share of pixels showing grass is nearer
    // the reference's (here 0.0096 against 0.029).
    int blade_pixels = 0;
    const double with = grass::test::tile_coverage_error(low, low_image, 8, &blade_pixels);
    const double without = grass::test::tile_coverage_error(low, low_plain);
    CAPTURE(blade_pixels);
    CAPTURE(with);
    CAPTURE(without);
    CHECK(blade_pixels > 300);
    CHECK(with < 0.5 * without);
    const auto [high_timing, high_image] = frame(high, hilltops);
    CHECK(counter(high_timing, "hilltop_draws") == 0);
    CHECK(max_difference(high_image, frame(high, plain).second) <= 1e-5f);
}

TEST_CASE("grass.lod quadtree: a band that keeps nothing this frame records no draw") {
    // On lavapipe an indirect draw of no instances still costs milliseconds: a band whose CPU
    // selection kept nothing must not record one. Every blade near, then every blade far.
    const Scene scene = lod_field_scene();
    for (const auto& [values, drawn] : {std::pair{quadtree_values(1e6, 1e6, 1e6, 1e6), std::string("near")},
                                        std::pair{quadtree_values(0, 0, 0, 0), std::string("far")}}) {
        CAPTURE(drawn);
        auto r = renderer(scene, "grass.lod", values);
        const FrameTiming t = r->render_counting_primitives(FrameState{});
        const std::vector<std::string> names = r->pass_names();
        REQUIRE(t.pass_draws.size() == names.size());
        // Each band's pass (near: the ground too) and its selection's count of instances.
        for (const auto& [band, pass] : {std::pair{"near", "blades"}, std::pair{"middle", "volume_volumes"},
                                         std::pair{"far", "image_slices"}}) {
            CAPTURE(band);
            const auto at = std::find(names.begin(), names.end(), pass);
            REQUIRE(at != names.end());
            const double kept = counter(t, std::string(band) + "_draws");
            CHECK((kept > 0) == (band == drawn));
            const uint32_t ground = std::string(band) == "near" ? 1 : 0;
            CHECK(t.pass_draws[size_t(at - names.begin())] == ground + (kept > 0 ? 1u : 0u));
        }
    }
}
