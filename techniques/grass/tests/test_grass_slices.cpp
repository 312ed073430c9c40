// grass.slices (Boulanger's BTF slices): each slice side's load-phase bake holds, texel by texel,
// the blade Embree's orthographic rays meet within that slice's section, its back side the same
// outline; seen from afar along either slice direction and from above, the slices cover what the
// reference's rays hit at about the depth they hit it; and with the sun along any of the five
// baked directions, the slices show exactly the colours grass.volume (from the side) and
// grass.image (from above) compute per pixel from the same bakes, on a mirrored field, so the
// baked rows, the light's weights, its mirroring and the choice of the side seen are all pinned.
// A slice baked from the wrong section, two rows swapped, the light not mirrored with its cell or
// the sides swapped fails a check here. A shadowed bake's rows hold, texel by texel, what rays
// towards each baked light find, and its slices show the shadowed reference's colours.
#include "support/bake_truth.hpp"

#include "core/registry.hpp"
#include "config/scene_config.hpp"
#include "reference/embree_scene.hpp"
#include "reference/primary_hit.hpp"
#include "reference/reference_renderer.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "support/reference_hits.hpp"
#include "support/test_gpu.hpp"

#include "../common/patch_bake.hpp"
#include "../shaders/bake_shadows.h"
#include "../shaders/btf_interpolation.h"
#include "../slices/slices_graph.hpp"

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
// Far away with a narrow view: nearly the orthographic views along -x, -z and -y.
const char* kFarAlongZ = "[camera]\nposition = [0.5, 0.12, 80]\ntarget = [0.5, 0.12, 0.5]\nfov = 0.9\nnear = 40\nfar = 120";
const char* kFarAlongX = "[camera]\nposition = [80, 0.12, 0.5]\ntarget = [0.5, 0.12, 0.5]\nfov = 0.9\nnear = 40\nfar = 120";
const char* kFarAlongMinusZ = "[camera]\nposition = [0.5, 0.12, -80]\ntarget = [0.5, 0.12, 0.5]\nfov = 0.9\nnear = 40\nfar = 120";
const char* kFarAlongMinusX = "[camera]\nposition = [-80, 0.12, 0.5]\ntarget = [0.5, 0.12, 0.5]\nfov = 0.9\nnear = 40\nfar = 120";
// Very far above the 2 x 2 field's centre, so that the vertical slices, seen edge-on, cover
// almost no pixel centre.
const char* kFarAboveField =
    "[camera]\nposition = [1, 1000, 1]\ntarget = [1, 0, 1]\nup = [0, 0, -1]\nfov = 0.13\nnear = 900\nfar = 1100";
const char* kFarAbove =
    "[camera]\nposition = [0.5, 80, 0.5]\ntarget = [0.5, 0, 0.5]\nup = [0, 0, -1]\nfov = 0.9\nnear = 40\nfar = 120";
// Inside the field, among the slices, looking across it.
const char* kInside = "[camera]\nposition = [0.05, 0.06, 0.1]\ntarget = [1, 0.04, 0.7]\nnear = 0.001\nfov = 60";

const Technique& technique(const char* name) {
    const Technique* t = TechniqueRegistry::instance().find(name);
    REQUIRE(t);
    return *t;
}

// Level 0 alone, unfiltered (mip_filter = "none", bake_supersampling = 1): each texel one blade,
// as the texel-by-texel checks against the rays need; filtering is test_grass_coverage's and
// test_mip_filters'.
FrameRenderer slices_renderer(const Scene& scene, uint32_t width, uint32_t height, bool neighbours = false,
                              long long shadow_resolution = 0) {
    const ParamSet params = ParamSet::resolve(technique("grass.slices").params(),
                                              {{"slices", (long long)kSlices},
                                               {"resolution", (long long)kWidth},
                                               {"height_resolution", (long long)kHeight},
                                               {"neighbours", neighbours},
                                               {"shadow_resolution", shadow_resolution},
                                               {"mip_filter", std::string("none")},
                                               {"bake_supersampling", 1LL}},
                                              {}, {}, "grass.slices");
    return FrameRenderer(test::gpu(), scene, build_scene_meshes(scene), width, height,
                         technique("grass.slices").graph(params));
}

// grass.image baking the same top view as slices_renderer.
FrameRenderer image_renderer(const Scene& scene, uint32_t width, uint32_t height) {
    const ParamSet params = ParamSet::resolve(
        technique("grass.image").params(),
        {{"resolution", (long long)kWidth}, {"mip_filter", std::string("none")}, {"bake_supersampling", 1LL}}, {}, {},
        "grass.image");
    return FrameRenderer(test::gpu(), scene, build_scene_meshes(scene), width, height,
                         technique("grass.image").graph(params));
}

Bounds prototype_bounds(const Scene& scene) {
    Bounds b;
    for (const Vertex& v : scene.populations.at(0).family->prototype.vertices) b.extend(v.position);
    return b;
}

// 2 x 2 cells of the one-cell patch, each mirrored its own way (this seed mirrors some in x and
// some in z).
Scene mirrored_field(const std::string& camera) {
    return parse_scene(std::string("[scene]\nname = \"field\"\nambient = 0.2\n") + camera +
                           "\n[[light]]\ntype = \"directional\"\ndirection = [0, -1, 0]\ncasts_shadows = false\n"
                           "[[population]]\nname = \"patch\"\nkind = \"grass\"\nalbedo = [0.1, 0.8, 0.1]\n"
                           "params = { cells_x = 2, cells_z = 2, centre_x = 1, centre_z = 1, mirror = true, mirror_seed = 3, "
                           "blades = 60, subdivisions = 3, width_min = 0.06, width_max = 0.1 }\n",
                       "field.toml");
}

// A technique's colours against the reference's (one sample at each pixel centre, the scene's
// shading), where the reference's ray hits a blade off the edges between blades and the technique
// shows grass: how many differ by more than 5 % in green, and the mean relative difference.
struct ColourAgreement {
    int both = 0, off = 0;
    double mean_relative = 0.0;
};

ColourAgreement compare_with_reference_colours(const Scene& scene, const Image& image) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    const int width = image.width, height = image.height;
    ReferenceSettings settings;
    settings.pixel_samples = 1;
    settings.light_samples = 1;
    const ReferenceImages reference = render_reference(scene, embree, uint32_t(width), uint32_t(height), settings);
    const auto hits = test::reference_hits(scene, embree, uint32_t(width), uint32_t(height));
    const uint32_t per_blade = 2 * (uint32_t(scene.populations.at(0).params.integer("subdivisions")) + 1);
    const auto label = [&](int x, int y) -> int64_t {
        const auto& h = hits[size_t(y) * size_t(width) + size_t(x)];
        return h && h->what.population >= 0 ? int64_t(h->hit.primitive / per_blade) : -1;
    };
    ColourAgreement a;
    for (int y = 1; y + 1 < height; ++y)
        for (int x = 1; x + 1 < width; ++x) {
            const int64_t blade = label(x, y);
            if (blade < 0 || !grass::test::shows_grass(image.at(x, y))) continue;
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) edge = edge || label(x + dx, y + dy) != blade;
            if (edge) continue;
            const double want = reference.radiance.at(x, y)[1], got = image.at(x, y)[1];
            const double relative = std::abs(got - want) / std::max(want, 1e-3);
            ++a.both;
            a.off += relative > 0.05;
            a.mean_relative += relative;
        }
    if (a.both > 0) a.mean_relative /= a.both;
    return a;
}

// grass.slices (baked alone; shadowed with `shadow_resolution` > 0) on `scene` at 160 x 120, its
// image in `color`, against the reference's colours.
ColourAgreement slices_colours_against_reference(const Scene& scene, long long shadow_resolution, Image& color) {
    FrameRenderer slices = slices_renderer(scene, 160, 120, false, shadow_resolution);
    slices.render();
    color = slices.read_color();
    for (float v : color.pixels) REQUIRE(std::isfinite(v));
    return compare_with_reference_colours(scene, color);
}

struct Agreement {
    int both = 0;       // pixels where both show grass
    int coverage = 0;   // where one shows grass and the other not
    int colour = 0;     // of `both`, where the colours differ by more than the tolerance
    double worst = 0.0;
};

Agreement compare_images(const Image& a, const Image& b, float tolerance) {
    Agreement r;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const bool ga = grass::test::shows_grass(a.at(x, y)), gb = grass::test::shows_grass(b.at(x, y));
            if (ga != gb) ++r.coverage;
            if (!ga || !gb) continue;
            ++r.both;
            double d = 0.0;
            for (int c = 0; c < 3; ++c) d = std::max(d, double(std::abs(a.at(x, y)[c] - b.at(x, y)[c])));
            r.worst = std::max(r.worst, d);
            r.colour += d > tolerance;
        }
    return r;
}

}  // namespace

TEST_CASE("grass.slices: each slice side's bake shows the blades of its own section, texel by texel") {
    const Scene scene = one_cell_scene(kAnyCamera, "density = 1.0");
    FrameRenderer renderer = slices_renderer(scene, 64, 48);
    renderer.render();
    const Bounds b = prototype_bounds(scene);
    int covered = 0;
    for (uint32_t axis = 0; axis < 2; ++axis)
        for (uint32_t k = 0; k < kSlices; ++k) {
            CAPTURE(axis);
            CAPTURE(k);
            const Image front = renderer.read_image("slices_albedo", 0, grass::slice_side_layer(axis, k, 0, kSlices));
            const Image back = renderer.read_image("slices_albedo", 0, grass::slice_side_layer(axis, k, 1, kSlices));
            const Image front_blades = renderer.read_image("slices_blades", 0, grass::slice_side_layer(axis, k, 0, kSlices));
            const Image back_blades = renderer.read_image("slices_blades", 0, grass::slice_side_layer(axis, k, 1, kSlices));
            REQUIRE(front.width == int(kWidth));
            REQUIRE(front.height == int(kHeight));
            const float lo = axis == 0 ? b.min.x : b.min.z, hi = axis == 0 ? b.max.x : b.max.z;
            const float step = (hi - lo) / float(kSlices);
            const grass::test::Section section{k == 0 ? -1e30f : lo + step * float(k),
                                               k + 1 == kSlices ? 1e30f : lo + step * float(k + 1)};
            const auto view = axis == 0 ? grass::test::View::along_x : grass::test::View::along_z;
            const auto truth = grass::test::traced_bake(scene, view, kWidth, kHeight, section);
            const grass::test::BakeAgreement same = grass::test::compare_bake(front, front_blades, truth);
            CAPTURE(same.compared);
            CAPTURE(same.covered);
            CAPTURE(same.coverage);
            CHECK(same.coverage <= same.compared / 1000);
            CHECK(same.threshold <= same.compared / 1000);
            CHECK(same.root <= same.compared / 1000);
            covered += same.covered;
            // Seen from behind, the section has the same outline (the blade in front may differ).
            CHECK(grass::test::compare_bake(back, back_blades, truth).coverage <= same.compared / 1000);
            // The neighbouring section's blades are not this one's.
            if (k + 1 < kSlices) {
                const grass::test::Section next{section.hi, k + 2 == kSlices ? 1e30f : lo + step * float(k + 2)};
                const auto other = grass::test::traced_bake(scene, view, kWidth, kHeight, next);
                CHECK(grass::test::compare_bake(front, front_blades, other).coverage > same.coverage + 20);
            }
            for (float v : front.pixels) REQUIRE(std::isfinite(v));
            for (float v : back.pixels) REQUIRE(std::isfinite(v));
        }
    CHECK(covered > 1000);
    // The horizontal slice: the patch from above.
    const Image top = renderer.read_image("top_albedo");
    const auto truth = grass::test::traced_bake(scene, grass::test::View::down, kWidth);
    const grass::test::BakeAgreement same = grass::test::compare_bake(top, renderer.read_image("top_blades"), truth);
    CHECK(same.covered > 300);
    CHECK(same.coverage <= same.compared / 1000);
    CHECK(same.threshold <= same.compared / 1000);
    CHECK(same.root <= same.compared / 1000);
}

TEST_CASE("grass.slices: seen from afar along either slice direction and from above, the slices cover what the reference's rays hit") {
    for (const bool neighbours : {false, true})
        for (const char* camera : {kFarAlongZ, kFarAlongX, kFarAbove}) {
            CAPTURE(camera);
            CAPTURE(neighbours);
            const Scene scene = one_cell_scene(camera, "density = 1.0");
            FrameRenderer renderer = slices_renderer(scene, 160, 120, neighbours);
            renderer.render();
            const auto [color, visibility] = renderer.read_color_and_pixel_visibility();
            // The depth is the slice's plane: within half a section's width of the blade.
            const Bounds b = prototype_bounds(scene);
            const float tolerance = 0.5f * (b.max.x - b.min.x) / float(kSlices) + 0.01f;
            const grass::test::CoverageAgreement a =
                grass::test::compare_with_reference_hits(scene, color, &visibility, tolerance);
            CAPTURE(a.compared);
            CAPTURE(a.covered);
            CAPTURE(a.differ);
            CAPTURE(a.depth_off);
            CHECK(a.covered > 300);
            // Baked with its neighbours, the cell shows the blades leaning in from them and cuts
            // its own at its sides, which the one-cell reference does not: a few per cent.
            CHECK(a.differ <= a.compared / (neighbours ? 50 : 1000));
            if (camera != kFarAbove) CHECK(a.depth_off <= a.depth_compared / (neighbours ? 10 : 100));
        }
}

TEST_CASE("grass.slices: with the sun along each baked direction, the slices seen along an axis from any side show the reference's colours") {
    // Seen along an axis (nearly orthographically), the nearest slice showing a blade at a pixel
    // shows the nearest blade of the nearest section that has one there: the blade the
    // reference's ray hits, seen from the same side, lit by exactly one baked row.
    int compared = 0;
    for (int row = 0; row < shader::BTF_LIGHTS; ++row)
        for (const char* camera : {kFarAlongX, kFarAlongZ, kFarAlongMinusX, kFarAlongMinusZ}) {
            CAPTURE(row);
            CAPTURE(camera);
            Scene scene = one_cell_scene(camera, "density = 1.0");
            scene.lights.at(0).direction = -shader::btf_light_direction(row);
            Image color;
            const ColourAgreement same = slices_colours_against_reference(scene, 0, color);
            CAPTURE(same.both);
            CAPTURE(same.off);
            CAPTURE(same.mean_relative);
            CHECK(same.both > 200);
            // Vertex-interpolated normals and the RGBA16F rows agree to a few per cent; the
            // slices' planes a texel off the ray's first blade account for the rest.
            CHECK(same.off <= same.both / 20);
            CHECK(same.mean_relative < 0.02);
            compared += same.both;
        }
    CHECK(compared > 4000);
}

TEST_CASE("grass.slices: a shadowed bake: with the sun along each baked direction, the slices show the shadowed reference's colours") {
    // The same views against Embree with shadow rays: the one cell's blades shadow each other, and
    // the bake (alone, as the reference's one cell) holds those shadows in its rows' alpha.
    int compared = 0, grass = 0, shadowed = 0;
    for (int row = 0; row < shader::BTF_LIGHTS; ++row)
        for (const char* camera : {kFarAlongX, kFarAlongZ, kFarAlongMinusX, kFarAlongMinusZ}) {
            CAPTURE(row);
            CAPTURE(camera);
            Scene scene = one_cell_scene(camera, "density = 1.0");
            scene.lights.at(0).direction = -shader::btf_light_direction(row);
            scene.lights.at(0).casts_shadows = true;
            Image color;
            const ColourAgreement same = slices_colours_against_reference(scene, 1024, color);
            CAPTURE(same.both);
            CAPTURE(same.off);
            CAPTURE(same.mean_relative);
            CHECK(same.both > 200);
            // Looser than unshadowed: at 80 units the reference starts its shadow rays 5 mm off
            // the blade (light_integrator.hpp's offset), a pixel here, which moves its shadow
            // edges on blades a grazing light meets by about a pixel, and a baked texel is 1.3
            // pixels (up to 7 % of the pixels off, relative mean up to 0.124, with the sun across
            // the view). The texel-by-texel check below holds the bake to the light's own rays.
            CHECK(same.off <= same.both / 10);
            CHECK(same.mean_relative < 0.15);
            compared += same.both;
            // The same view unshadowed: how many of its pixels the shadows darken.
            Scene local = scene;
            local.lights.at(0).casts_shadows = false;
            FrameRenderer unshadowed = slices_renderer(local, 160, 120);
            unshadowed.render();
            const Image lit = unshadowed.read_color();
            for (int y = 0; y < color.height; ++y)
                for (int x = 0; x < color.width; ++x)
                    if (grass::test::shows_grass(color.at(x, y)) && grass::test::shows_grass(lit.at(x, y))) {
                        ++grass;
                        shadowed += color.at(x, y)[1] < 0.8f * lit.at(x, y)[1];
                    }
        }
    CHECK(compared > 4000);
    CAPTURE(grass);
    CAPTURE(shadowed);
    CHECK(shadowed > grass / 20);  // 12 %: most views have the sun behind or across them
}

namespace {

// 3 x 3 unmirrored cells of the one-cell patch around the cell at [0, 1]^2: what a tiled bake draws.
Scene tiled_field() {
    return parse_scene(std::string("[scene]\nname = \"tiled\"\nambient = 0.2\n") + kAnyCamera +
                           "\n[[light]]\ntype = \"directional\"\ndirection = [0, -1, 0]\ncasts_shadows = false\n"
                           "[[population]]\nname = \"patch\"\nkind = \"grass\"\nalbedo = [0.1, 0.8, 0.1]\n"
                           "params = { cells_x = 3, cells_z = 3, centre_x = 0.5, centre_z = 0.5, mirror = false, "
                           "blades = 60, subdivisions = 3, width_min = 0.06, width_max = 0.1, density = 1.0 }\n",
                       "tiled.toml");
}

struct ShadowAgreement {
    int compared = 0, shadowed = 0, off = 0;
};

// A shadowed bake of `scene`'s patch (tiled: with its 8 neighbours, `scene` being tiled_field()),
// each vertical slice's front side and the horizontal slice: where the bake and Embree's
// orthographic rays see the same blade, each row's alpha (the light's visibility) against a ray
// from the blade point towards the light, started 1e-4 along it.
ShadowAgreement shadowed_bake_against_rays(const Scene& scene, bool tiled) {
    FrameRenderer renderer = slices_renderer(scene, 64, 48, tiled, 1024);
    renderer.render();
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    Camera towards = scene.camera;
    towards.near_plane = 0.0f;
    towards.far_plane = 1e30f;
    const Bounds b = prototype_bounds(scene);
    const Bounds frame = tiled ? grass::cell_frame(b) : b;
    ShadowAgreement a;
    // (axis, k) of the vertical slices' front sides, then the horizontal slice (axis 2).
    for (uint32_t axis = 0; axis < 3; ++axis)
        for (uint32_t k = 0; k < (axis == 2 ? 1 : kSlices); ++k) {
            const bool top = axis == 2;
            const uint32_t width = kWidth, height = top ? kWidth : kHeight;
            const float lo = axis == 0 ? frame.min.x : frame.min.z, hi = axis == 0 ? frame.max.x : frame.max.z;
            const float step = (hi - lo) / float(kSlices);
            grass::test::Section section{lo + step * float(k), lo + step * float(k + 1)};
            if (!tiled && k == 0) section.lo = -1e30f;
            if (!tiled && k + 1 == kSlices) section.hi = 1e30f;
            if (top) section = {};
            const auto view = axis == 0 ? grass::test::View::along_x : axis == 1 ? grass::test::View::along_z : grass::test::View::down;
            const auto truth = grass::test::traced_bake_over(scene, frame, view, width, height, section);
            const uint32_t layer = top ? 0 : grass::slice_side_layer(axis, k, 0, kSlices);
            const Image albedo = top ? renderer.read_image("top_albedo") : renderer.read_image("slices_albedo", 0, layer);
            const Image blades = top ? renderer.read_image("top_blades") : renderer.read_image("slices_blades", 0, layer);
            REQUIRE(albedo.width == int(width));
            REQUIRE(albedo.height == int(height));
            for (int row = 0; row < shader::BTF_LIGHTS; ++row) {
                CAPTURE(axis);
                CAPTURE(k);
                CAPTURE(row);
                const Image lit = top ? renderer.read_image("top_lit", 0, uint32_t(row))
                                      : renderer.read_image("slices_lit", 0, layer * uint32_t(shader::BTF_LIGHTS) + uint32_t(row));
                const glm::vec3 l = shader::btf_light_direction(row);
                for (int j = 1; j + 1 < int(height); ++j)
                    for (int i = 1; i + 1 < int(width); ++i) {
                        const auto& t = truth[size_t(j) * width + size_t(i)];
                        bool edge = false;
                        for (int dj = -1; dj <= 1; ++dj)
                            for (int di = -1; di <= 1; ++di)
                                edge = edge || truth[size_t(j + dj) * width + size_t(i + di)].blade != t.blade;
                        if (edge || t.blade < 0 || albedo.at(i, j)[3] != 1.0f || blades.at(i, j)[0] != t.threshold) continue;
                        const float baked = lit.at(i, j)[3];
                        REQUIRE(baked >= 0.0f);
                        REQUIRE(baked <= 1.0f);
                        const Ray ray{t.position + 1e-4f * l, l};
                        const bool visible = !trace_primary(embree, towards, l, ray);
                        ++a.compared;
                        a.shadowed += !visible;
                        a.off += std::abs(baked - (visible ? 1.0f : 0.0f)) > 0.5f;
                    }
            }
        }
    return a;
}

}  // namespace

TEST_CASE("grass.slices: a shadowed bake holds, texel by texel, whether Embree's ray towards each baked light leaves the patch") {
    // Alone, as the one cell Embree holds; tiled (the default), as the cell of a 3 x 3 field.
    for (const bool tiled : {false, true}) {
        CAPTURE(tiled);
        const ShadowAgreement a = shadowed_bake_against_rays(tiled ? tiled_field() : one_cell_scene(kAnyCamera, "density = 1.0"), tiled);
        CAPTURE(a.compared);
        CAPTURE(a.shadowed);
        CAPTURE(a.off);
        CHECK(a.compared > 5000);
        CHECK(a.shadowed > a.compared / 10);
        // About 1 % differ: blades closer than the lookup's offsets (2.5 light-view texels) and the
        // 2 x 2 compare at shadow edges.
        CHECK(a.off <= a.compared / 50);
    }
}

TEST_CASE("grass.slices: a shadowed bake's shadows thin with the cell's density (eq 4.7)") {
    // With the sun across the view: each pixel's colour with the shadowed bake over its colour with
    // the unshadowed one, at the same density (the same blades). At density 1 a shadowed blade
    // keeps only the ambient light; at 0.5, eq 4.7 keeps at least half of the direct light.
    float lowest[2] = {1e30f, 1e30f};
    for (const int half : {0, 1}) {
        Scene scene = one_cell_scene(kFarAlongZ, half ? "density = 0.5" : "density = 1.0");
        scene.lights.at(0).direction = -shader::btf_light_direction(1);
        FrameRenderer shadowed = slices_renderer(scene, 160, 120, false, 1024);
        FrameRenderer unshadowed = slices_renderer(scene, 160, 120);
        shadowed.render();
        unshadowed.render();
        const Image a = shadowed.read_color(), b = unshadowed.read_color();
        int both = 0;
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x)
                if (grass::test::shows_grass(a.at(x, y)) && grass::test::shows_grass(b.at(x, y))) {
                    ++both;
                    lowest[half] = std::min(lowest[half], a.at(x, y)[1] / b.at(x, y)[1]);
                }
        CHECK(both > 200);
    }
    CAPTURE(lowest[0]);
    CAPTURE(lowest[1]);
    CHECK(lowest[0] < 0.45f);
    CHECK(lowest[1] >= 0.5f - 1e-3f);
}

TEST_CASE("grass.slices: a shadowed bake's light views look along each baked direction, depth rising away from the light") {
    Bounds bounds;
    bounds.extend(glm::vec3(0.1f, 0.0f, 0.2f));
    bounds.extend(glm::vec3(0.9f, 0.4f, 0.7f));
    const float margin = 0.01f;
    for (const bool tiled : {false, true})
        for (uint32_t row = 0; row < uint32_t(shader::BTF_LIGHTS); ++row) {
            CAPTURE(tiled);
            CAPTURE(row);
            const Bounds frame = grass::light_frame(bounds, row, tiled, margin);
            const glm::mat4 view = grass::light_bake(bounds, row, tiled, margin).view_proj;
            const glm::vec3 centre = 0.5f * (frame.min + frame.max), l = shader::btf_light_direction(int(row));
            const glm::vec3 half = 0.5f * (frame.max - frame.min);
            const glm::vec4 near = view * glm::vec4(centre + l * glm::dot(glm::abs(l), half), 1.0f);
            const glm::vec4 far = view * glm::vec4(centre - l * glm::dot(glm::abs(l), half), 1.0f);
            CHECK(near.z == doctest::Approx(0.0f).epsilon(1e-5));
            CHECK(far.z == doctest::Approx(1.0f).epsilon(1e-5));
            // Every corner of the frame inside the view.
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 p((corner & 1) ? frame.max.x : frame.min.x, (corner & 2) ? frame.max.y : frame.min.y,
                                  (corner & 4) ? frame.max.z : frame.min.z);
                const glm::vec4 c = view * glm::vec4(p, 1.0f);
                CHECK(std::abs(c.x) <= 1.0f + 1e-5f);
                CHECK(std::abs(c.y) <= 1.0f + 1e-5f);
            }
            if (tiled) {
                // Across the light: the cell and the margin; along it: the neighbours (x, z in
                // [-1, 2]) or the blades' height.
                const int axis = grass::light_axis(row);
                CHECK(std::abs(glm::dot(l, glm::vec3(axis == 0, axis == 1, axis == 2))) == 1.0f);
                for (const int other : {0, 2})
                    if (other != axis) {
                        CHECK(frame.min[other] == doctest::Approx(-margin));
                        CHECK(frame.max[other] == doctest::Approx(1.0f + margin));
                    } else {
                        CHECK(frame.min[other] == -1.0f);
                        CHECK(frame.max[other] == 2.0f);
                    }
                CHECK(frame.min.y == 0.0f);
                CHECK(frame.max.y == doctest::Approx(0.4f));
            }
            // The lookup compares a point's depth moved `bias` towards the light.
            const glm::mat4 lookup = grass::light_lookup(bounds, row, tiled, margin, 0.01f);
            const glm::vec3 moved = shader::bake_shadow_coord(lookup, centre);
            const glm::vec4 towards = view * glm::vec4(centre + 0.01f * l, 1.0f);
            CHECK(moved.z == doctest::Approx(towards.z).epsilon(1e-5));
        }
}

TEST_CASE("grass.slices: eq 4.7 thins a baked shadow by the cell's density, and stays in [0, 1]") {
    CHECK(shader::bake_shadow_at_density(0.2f, 1.0f) == doctest::Approx(0.2f));
    CHECK(shader::bake_shadow_at_density(0.2f, 0.0f) == 1.0f);
    CHECK(shader::bake_shadow_at_density(0.2f, 0.5f) == doctest::Approx(0.6f));
    CHECK(shader::bake_shadow_at_density(1.0f, 0.7f) == 1.0f);  // unshadowed rows stay exactly as baked
    for (float v : {-1.0f, 0.0f, 0.5f, 1.0f, 2.0f, 1e30f})
        for (float d : {-1.0f, 0.0f, 0.3f, 1.0f, 5.0f, 1e30f}) {
            const float r = shader::bake_shadow_at_density(v, d);
            CHECK(r >= 0.0f);
            CHECK(r <= 1.0f);
        }
}

TEST_CASE("grass.slices: with the sun along each baked direction, the horizontal slice from above shows grass.image's colours on a mirrored field") {
    // The same top-view bake: grass.image lights its texel per pixel with the world's light and the
    // mirrored normal, grass.slices with the baked row of the light mirrored into the cell.
    int compared = 0;
    for (int row = 0; row < shader::BTF_LIGHTS; ++row) {
        CAPTURE(row);
        Scene scene = mirrored_field(kFarAboveField);
        scene.lights.at(0).direction = -shader::btf_light_direction(row);
        FrameRenderer slices = slices_renderer(scene, 160, 120);
        slices.render();
        FrameRenderer image = image_renderer(scene, 160, 120);
        image.render();
        const Image a = slices.read_color(), b = image.read_color();
        for (float v : a.pixels) REQUIRE(std::isfinite(v));
        const Agreement same = compare_images(a, b, 4e-3f);
        CAPTURE(same.both);
        CAPTURE(same.coverage);
        CAPTURE(same.colour);
        CAPTURE(same.worst);
        CHECK(same.both > 2000);
        CHECK(same.colour <= same.both / 200);
        CHECK(same.coverage <= same.both / 200);
        compared += same.both;
    }
    CHECK(compared > 10000);
}

TEST_CASE("grass.slices: extremes: an eye among the slices, the sun at the zenith and the horizon, density 0 and 1, baked with and without shadows") {
    for (const char* camera : {kInside, kAnyCamera})
        for (const glm::vec3 sun : {glm::vec3(0, -1, 0), glm::vec3(1, 0, 0), glm::vec3(0.3f, -1e-7f, -1.0f)})
            for (const char* density : {"density = 1.0", "density = 0.0", "density = 0.5"})
                for (const long long shadow_resolution : {0ll, 256ll}) {
                    CAPTURE(camera);
                    CAPTURE(density);
                    CAPTURE(shadow_resolution);
                    Scene scene = one_cell_scene(camera, density);
                    scene.lights.at(0).direction = glm::normalize(sun);
                    FrameRenderer renderer = slices_renderer(scene, 96, 64, true, shadow_resolution);
                    renderer.render();
                    const Image color = renderer.read_color();
                    for (float v : color.pixels) REQUIRE(std::isfinite(v));
                    const int grass = grass::test::grass_pixels(color);
                    if (std::string(density) == "density = 0.0") CHECK(grass == 0);
                    else CHECK(grass > 200);
                }
}

TEST_CASE("grass.slices on a terrain: quads cut at the ground's diagonal and lifted onto it cover the reference's "
          "lifted blades") {
    // height_scale 0 is the same field flat. From a standing eye the vertical slices show; from
    // high above, the horizontal one.
    // Measured: 0.64 times the flat field's error standing (the slopes face the eye) and 1.27 times
    // from above; with the quads left at their cell's corner height, 1.39 and 1.49 times. The cut's
    // place and the horizontal quad's split change these by 0.04 at most, below what tiles of
    // coverage resolve: grass_diagonal_crossing's own test pins the cut.
    const std::pair<const char*, double> views[] = {
        {"[camera]\nposition = [0.0, 2.5, 4.5]\ntarget = [0.0, 0.3, 0.0]\nfov = 45", 1.0},
        {"[camera]\nposition = [0.0, 7.0, 3.5]\ntarget = [0.0, 0.3, 0.0]\nfov = 40", 1.38}};
    for (const auto& [camera, bound] : views)
        grass::test::check_follows_terrain(camera, bound, [](const Scene& scene) {
            FrameRenderer renderer = slices_renderer(scene, 200, 120, true);
            renderer.render();
            return renderer.read_color();
        });
}

TEST_CASE("grass.slices: what only the load phase uses (the bake's depth targets, a shadowed bake's light views) is "
          "released once the load has run, and the frames still render") {
    const Scene scene = one_cell_scene(kAnyCamera, "density = 1");
    FrameRenderer shadowed = slices_renderer(scene, 64, 48, true, 32);
    const MemoryUse memory = shadowed.memory();
    // The depth targets (D32: a vertical slice's bake, the horizontal one's) and the five light views.
    const uint64_t load_only_images = 4ull * (kWidth * kHeight + kWidth * kWidth + 32ull * 32ull * 5ull);
    CAPTURE(memory.technique_bytes);
    CAPTURE(memory.technique_peak_bytes);
    CHECK(memory.technique_peak_bytes >= memory.technique_bytes + load_only_images);
    // What the frames read is kept: the slices' albedo alone is 4n layers of RGBA32F.
    CHECK(memory.technique_bytes >= 16ull * kWidth * kHeight * 4ull * kSlices);
    for (const char* released : {"bake_light_depth", "bake_depth", "top_bake_depth"}) {
        CAPTURE(released);
        try {
            (void)shadowed.read_image(released);
            FAIL("a released image was read");
        } catch (const std::logic_error& e) {
            CHECK(std::string(e.what()).find("released after the load phase") != std::string::npos);
        }
    }
    shadowed.render();
    const Image first = shadowed.read_color();
    shadowed.render();
    const Image second = shadowed.read_color();
    CHECK(first.pixels == second.pixels);
    int covered = 0;
    for (int y = 0; y < first.height; ++y)
        for (int x = 0; x < first.width; ++x) covered += grass::test::shows_grass(first.at(x, y));
    CHECK(covered > 100);
}
