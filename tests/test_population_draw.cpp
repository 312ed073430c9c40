// A technique that renders a population (issue 9, item 7), as a test-only frame graph (not in
// the technique registry): it declares GraphNeeds::populations = {"scatter"}, draws the scene's
// objects with draw_scene and each population in one instanced draw (PassContext::
// draw_population, harness/shaders/population.vert), and writes the lit pass's visibility.
// Checked two ways, each with breakages that must fail it (the test shows it can):
//   - against the Embree reference: at every pixel centre outside a 1-pixel band around the
//     reference's silhouettes (where one surface meets another), the raster image shows the
//     population exactly where the reference's primary ray hits it, at the same depth;
//     the reference built from a different seed, one copy fewer or copies shifted by 2 pixels
//     disagrees;
//   - against the same scene with the copies written out as explicit objects: bit for bit the
//     same colour and depth; one copy dropped, or copies moved by 0.01, differ.
//   - with an alpha mask (harness/shaders/alpha_mask.h): the raster's cuts and the reference's
//     pass-through rays agree at every pixel centre off the edges; a raster or a reference that
//     ignores the mask, wider slots or slots across another axis disagree.
#include "graph/frame_graph.hpp"
#include "graph/pass_context.hpp"
#include "reference/embree_scene.hpp"
#include "reference/primary_hit.hpp"
#include "render/frame_renderer.hpp"
#include "render/frame_uniforms.hpp"
#include "config/scene_config.hpp"
#include "core/pixel_visibility.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"
#include "scene/population.hpp"
#include "support/reference_hits.hpp"
#include "support/test_gpu.hpp"

#include "alpha_mask.h"
#include "shaders/tests/population_flat_frag.h"
#include "shaders/tests/population_masked_frag.h"
#include "shaders/harness/population_vert.h"
#include "shaders/harness/scene_vert.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

using namespace canopy;

namespace {

constexpr uint32_t kWidth = 192, kHeight = 144;

// Boxes and spheres on a floor, seen obliquely from above: copies of different sizes and yaws,
// some overlapping, one object (a tall box) hiding some.
const char* kScene = R"(
[scene]
name = "scatter-field"
[camera]
position = [0, 5.5, 4.5]
target = [0, 0, 0.3]
fov = 45
near = 0.1
far = 30
[[light]]
type = "directional"
direction = [0, -1, 0]
[[object]]
name = "floor"
shape = "plane"
size = [8, 8]
albedo = 0.6
[[object]]
name = "post"
shape = "box"
size = [0.3, 1.2, 0.3]
translate = [0.4, 0.6, 0.2]
albedo = [0.2, 0.3, 0.8]
[[population]]
name = "crates"
kind = "scatter"
count = 40
region_min = [-2.2, -1.6]
region_max = [2.2, 1.8]
seed = 11
scale = [0.6, 1.4]
prototype = { shape = "box", size = [0.3, 0.2, 0.18], translate = [0, 0.1, 0], albedo = [0.9, 0.2, 0.1] }
)";

Scene field() { return parse_scene(kScene, "scatter-field.toml"); }

// Fewer, larger copies with slots cut across their x axis: each slab about 5 pixels wide. The
// boxes stand 1 cm off the ground: a bottom face on the ground would show through the slots in a
// depth tie with it, which the rasteriser and Embree break differently from one CPU to another
// (14 pixels on an AVX-512 AMD EPYC).
const char* kMaskedPopulation = R"(
[[population]]
name = "slatted"
kind = "scatter"
count = 12
region_min = [-2.2, -1.6]
region_max = [2.2, 1.8]
seed = 5
scale = [0.9, 1.2]
prototype = { shape = "box", size = [0.9, 0.5, 0.6], translate = [0, 0.26, 0], albedo = [0.9, 0.2, 0.1] }
alpha_mask = { kind = "stripes", axis = "x", period = 0.4, opaque = 0.5 }
)";

Scene slatted_field() {
    std::string text = kScene;
    text.erase(text.find("[[population]]"));
    return parse_scene(text + kMaskedPopulation, "slatted-field.toml");
}

// --- The test technique's frame graph ---------------------------------------------------------

RasterState scene_state() {
    RasterState s;
    s.vertex_spirv = scene_vert;
    s.fragment_spirv = population_flat_frag;
    return s;
}

RasterState population_state() {
    RasterState s = scene_state();
    s.vertex_spirv = population_vert;
    s.vertices = VertexLayout::population();
    return s;
}

FrameGraph population_graph(std::span<const uint32_t> population_fragment = population_flat_frag) {
    FrameGraph g;
    g.needs.populations = {population_kinds::kScatter};
    PassDecl lit{.name = "lit", .kind = PassKind::raster};
    lit.uses = {ResourceUse{.resource = graph_names::kFrameUniforms, .use = Use::uniform, .binding = 0},
                ResourceUse{.resource = graph_names::kColor, .use = Use::color_attachment,
                            .clear = std::array<float, 4>{0.0f, 0.0f, 0.0f, -1.0f}},  // VISIBILITY_NOT_LIT
                ResourceUse{.resource = graph_names::kDepth, .use = Use::depth_attachment,
                            .clear = std::array<float, 4>{1.0f, 0.0f, 0.0f, 0.0f}}};
    lit.push_constant_bytes = sizeof(DrawConstants);
    RasterState copies_state = population_state();
    copies_state.fragment_spirv = population_fragment;
    lit.record = [objects = scene_state(), copies = copies_state](PassContext& pc) {
        pc.bind(pc.raster_pipeline(objects));
        pc.draw_scene(SceneFilter::all);
        pc.bind(pc.raster_pipeline(copies));
        for (const GeneratedPopulation& population : pc.populations()) pc.draw_population(population.name);
    };
    g.passes.push_back(std::move(lit));
    return g;
}

struct Raster {
    Image color, visibility;
};

Raster render(const Scene& scene, std::span<const uint32_t> population_fragment = population_flat_frag) {
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight,
                           population_graph(population_fragment));
    renderer.render();
    FrameRenderer::ColorAndVisibility images = renderer.read_color_and_pixel_visibility();
    return {std::move(images.color), std::move(images.visibility)};
}

// The population's colour: red well above green (the floor and the post are grey and blue).
bool shows_population(const float* rgb) { return rgb[0] > 2.0f * rgb[1] && rgb[0] > 2.0f * rgb[2]; }

// --- The reference at pixel centres -----------------------------------------------------------

struct ReferencePixel {
    int64_t label = -1;  // what the ray sees: -1 background, else geometry and (for a population) copy
    bool population = false;
    float view_depth = 0.0f;
};

// A masked population's label also carries the mask's period under the hit and the side of its
// cut, so the silhouette band covers the mask's edges too (where float rounding may decide either way).
std::vector<ReferencePixel> reference_pixels(const Scene& scene) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    std::vector<std::vector<PopulationInstance>> copies;
    for (const Population& population : scene.populations) copies.push_back(*generate_instances(population));
    const std::vector<std::optional<test::ReferenceHit>> hits = test::reference_hits(scene, embree, kWidth, kHeight);
    std::vector<ReferencePixel> pixels(size_t(kWidth) * kHeight);
    for (size_t i = 0; i < hits.size(); ++i) {
        if (!hits[i]) continue;
        const PrimaryHit* hit = &hits[i]->hit;
        ReferencePixel& p = pixels[i];
        const EmbreeInstance& what = hits[i]->what;
        p.population = what.population >= 0;
        p.view_depth = hit->view_depth;
        // Copies of one population are one geometry: the copy tells their silhouettes apart.
        p.label = int64_t(hit->geometry) << 40;
        if (p.population) {
            const uint32_t copy = hit->primitive / what.prototype_triangles;
            p.label |= int64_t(copy) << 20;
            const Population& population = scene.populations[size_t(what.population)];
            if (population.alpha_mask.kind != AlphaMask::Kind::none) {
                const glm::mat4& model = copies[size_t(what.population)][copy].model;
                const glm::vec3 local = glm::vec3(glm::inverse(model) * glm::vec4(hit->surface.position, 1.0f));
                // Which period, and which side of the cut within it: both edges of a slot.
                const glm::vec4 mask = population.alpha_mask.packed();
                const int period = int(shader::alpha_mask_period_index(mask, local));
                const bool opaque = shader::alpha_mask_opaque(mask, local);
                // and the prototype's triangle: a slot may show the copy's own far side.
                p.label |= int64_t(hit->primitive % what.prototype_triangles) << 12;
                p.label |= int64_t((2 * period + (opaque ? 0 : 1)) & 0xfff);
            }
        }
    }
    return pixels;
}

struct Disagreement {
    int compared = 0;        // pixels outside the silhouette band
    int coverage = 0;        // of those: population in one image and not the other
    int depth = 0;           // of those: both show a surface, at depths more than 0.2 % apart
    int population_pixels = 0;  // reference pixels showing the population, outside the band
};

Disagreement compare_with_reference(const Raster& raster, const std::vector<ReferencePixel>& reference) {
    namespace pv = pixel_visibility;
    Disagreement d;
    const auto at = [&](int x, int y) -> const ReferencePixel& { return reference[size_t(y) * kWidth + size_t(x)]; };
    for (int y = 1; y + 1 < int(kHeight); ++y)
        for (int x = 1; x + 1 < int(kWidth); ++x) {
            bool silhouette = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) silhouette = silhouette || at(x + dx, y + dy).label != at(x, y).label;
            if (silhouette) continue;
            ++d.compared;
            const ReferencePixel& r = at(x, y);
            d.population_pixels += r.population;
            const bool raster_population = shows_population(raster.color.at(x, y));
            if (raster_population != r.population) ++d.coverage;
            const bool raster_surface = raster.visibility.at(x, y)[pv::kSurface] >= 0.5f;
            if (raster_surface != (r.label >= 0)) ++d.coverage;
            if (raster_surface && r.label >= 0 &&
                std::abs(raster.visibility.at(x, y)[pv::kViewDepth] - r.view_depth) > 2e-3f * r.view_depth)
                ++d.depth;
        }
    return d;
}

// The scene with the population's copies written out as objects, one per copy, in copy order:
// world = placement(k) * prototype, exactly as generate_instances composes it.
Scene with_explicit_copies(const Scene& scene, size_t drop_copy = SIZE_MAX, glm::vec3 shift = glm::vec3(0.0f)) {
    Scene explicit_scene = scene;
    explicit_scene.populations.clear();
    const Population& population = scene.populations.front();
    for (uint32_t k = 0; k < population.count; ++k) {
        if (k == drop_copy) continue;
        Object copy = population.prototype;
        copy.name = population.name + std::to_string(k);
        copy.instances.front().outer = scatter_placement(population, k);
        copy.instances.front().translate += shift;
        explicit_scene.objects.push_back(copy);
    }
    return explicit_scene;
}

struct ImageDifference {
    int color = 0, depth = 0;  // pixels whose colour or view depth differ at all
};

ImageDifference differences(const Raster& a, const Raster& b) {
    ImageDifference d;
    for (int y = 0; y < int(kHeight); ++y)
        for (int x = 0; x < int(kWidth); ++x) {
            d.color += std::memcmp(a.color.at(x, y), b.color.at(x, y), 4 * sizeof(float)) != 0;
            d.depth += a.visibility.at(x, y)[pixel_visibility::kViewDepth] !=
                       b.visibility.at(x, y)[pixel_visibility::kViewDepth];
        }
    return d;
}

}  // namespace

TEST_CASE("population draw: the instanced copies cover what the reference's primary rays hit, at its depths") {
    const Scene scene = field();
    const Raster raster = render(scene);
    const Disagreement same = compare_with_reference(raster, reference_pixels(scene));
    CAPTURE(same.compared);
    CAPTURE(same.population_pixels);
    CHECK(same.compared > int(kWidth * kHeight) / 2);
    CHECK(same.population_pixels > 500);  // the population is a sizeable part of the image
    CHECK(same.coverage == 0);
    CHECK(same.depth == 0);

    // Breakages on the reference's side alone: each must be seen.
    SUBCASE("another seed") {
        Scene other = scene;
        other.populations[0].seed += 1;
        const Disagreement d = compare_with_reference(raster, reference_pixels(other));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 200);
    }
    SUBCASE("one copy fewer") {
        Scene fewer = scene;
        fewer.populations[0].count -= 1;
        const Disagreement d = compare_with_reference(raster, reference_pixels(fewer));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 10);
    }
    SUBCASE("copies shifted by about 2 pixels") {
        Scene shifted = scene;
        shifted.populations[0].region_min.x += 0.08f;
        shifted.populations[0].region_max.x += 0.08f;
        const Disagreement d = compare_with_reference(raster, reference_pixels(shifted));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 100);
    }
}

TEST_CASE("population draw: an alpha-masked population is cut where the reference's rays pass through it") {
    const Scene scene = slatted_field();
    const Raster raster = render(scene, population_masked_frag);
    const Disagreement same = compare_with_reference(raster, reference_pixels(scene));
    CAPTURE(same.compared);
    CAPTURE(same.population_pixels);
    CHECK(same.compared > int(kWidth * kHeight) / 2);
    CHECK(same.population_pixels > 400);
    CHECK(same.coverage == 0);
    CHECK(same.depth == 0);

    // The cuts must show and agree: each breakage, on one side alone, must be seen.
    Scene solid = scene;
    solid.populations[0].alpha_mask = AlphaMask{};
    SUBCASE("the raster ignores the mask") {
        const Disagreement d = compare_with_reference(render(scene, population_flat_frag), reference_pixels(scene));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 100);  // 160 here
    }
    SUBCASE("the reference ignores the mask") {
        const Disagreement d = compare_with_reference(raster, reference_pixels(solid));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 150);
    }
    // The reference with its mask changed, against the raster with the scene's.
    const auto coverage_with_mask = [&](auto change) {
        Scene changed = scene;
        change(changed.populations[0].alpha_mask);
        return compare_with_reference(raster, reference_pixels(changed)).coverage;
    };
    SUBCASE("the reference cuts wider slots") {
        CHECK(coverage_with_mask([](AlphaMask& m) { m.opaque = 0.3f; }) > 50);  // 96 here
    }
    SUBCASE("the reference cuts across another axis") {
        CHECK(coverage_with_mask([](AlphaMask& m) { m.axis = 2; }) > 20);  // 319 here
    }
    // The fragment shader's mask discards: a masked shader on an unmasked population cuts nothing.
    const ImageDifference unmasked = differences(render(solid, population_masked_frag), render(solid, population_flat_frag));
    CHECK(unmasked.color == 0);
    CHECK(unmasked.depth == 0);
}

TEST_CASE("population draw: one instanced draw renders exactly what one object per copy renders") {
    const Scene scene = field();
    const Raster instanced = render(scene);
    const ImageDifference same = differences(instanced, render(with_explicit_copies(scene)));
    CHECK(same.color == 0);
    CHECK(same.depth == 0);

    // Breakages on the explicit side alone: each must be seen.
    const ImageDifference dropped = differences(instanced, render(with_explicit_copies(scene, 17)));
    CHECK(dropped.color > 10);
    const ImageDifference moved = differences(instanced, render(with_explicit_copies(scene, SIZE_MAX, glm::vec3(0.01f, 0, 0))));
    CHECK(moved.color > 10);
}

TEST_CASE("population draw: the harness uploads populations only for a graph that declares their kind") {
    const Scene scene = field();
    FrameGraph graph = population_graph();
    std::vector<size_t> seen;
    graph.passes.front().record = [&seen, objects = scene_state()](PassContext& pc) {
        seen.push_back(pc.populations().size());
        pc.bind(pc.raster_pipeline(objects));
        pc.draw_scene(SceneFilter::all);
        std::string refusal;
        try {
            pc.draw_population("nonesuch");
        } catch (const std::logic_error& error) {
            refusal = error.what();
        }
        CHECK(refusal.find("no population 'nonesuch'") != std::string::npos);
    };
    {
        FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight, graph);
        renderer.render();
        const MemoryUse with = renderer.memory();
        Scene bare = scene;
        bare.populations.clear();
        FrameRenderer without(test::gpu(), bare, build_scene_meshes(bare), kWidth, kHeight, graph);
        without.render();
        // The copies' buffer (40 x 128 bytes) and the prototype's 24 vertices and 36 indices.
        CHECK(with.scene_bytes >= without.memory().scene_bytes + 40 * sizeof(PopulationInstance));
    }
    REQUIRE(seen.size() == 2);
    CHECK(seen[0] == 1);
    CHECK(seen[1] == 0);
}

TEST_CASE("population draw: a buffer declared per copy is sized by the copies of the graph's kinds") {
    const Scene scene = field();  // 40 copies
    REQUIRE(generate_instances(scene.populations.at(0))->size() == 40);
    FrameGraph graph = population_graph();
    graph.buffers.push_back(
        {.name = "per_copy", .bytes = 16, .bytes_per_copy = 32, .usage = kStorageBuffer, .persistent = true});
    CHECK(validate(graph).empty());
    CHECK(describe(graph).find("buffer per_copy bytes=16+32/copy") != std::string::npos);
    PassDecl fill{.name = "fill", .kind = PassKind::copy, .phase = Phase::load};
    fill.uses = {ResourceUse{.resource = "per_copy", .use = Use::transfer_write}};
    std::string refusal;
    bool filled = false;
    fill.record = [&](PassContext& pc) {
        const std::vector<std::byte> bytes(16 + 40 * 32);
        pc.upload("per_copy", bytes.data(), bytes.size());  // fits exactly
        filled = true;
        try {
            pc.upload("per_copy", bytes.data(), 1, bytes.size());
        } catch (const std::logic_error& error) {
            refusal = error.what();
        }
    };
    graph.passes.insert(graph.passes.begin(), std::move(fill));
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight, graph);
    renderer.render();
    CHECK(filled);
    CHECK(refusal.find("uploads 1 bytes at 1296 into 'per_copy' of 1296 bytes") != std::string::npos);
}
