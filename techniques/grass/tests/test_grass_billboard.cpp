// grass.billboard: its load-phase bake is an orthographic view of the very blades the reference
// traces (checked texel by texel against Embree's rays: which blade, and its density threshold),
// and, seen from afar straight along -z, its crossed quads show what the reference's camera rays
// hit. A bake that flips its image, a quad that flips its texture coordinates or a cut that
// ignores the density fails a check here.
#include "../billboard/billboard_bake.h"

#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "reference/embree_scene.hpp"
#include "reference/primary_hit.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "scene/population_kind.hpp"
#include "support/reference_hits.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace canopy;

namespace {

constexpr uint32_t kBake = 128;  // the bake's resolution in these tests

// One unmirrored 1 x 1 cell whose copy sits at the origin: patch space is world space.
std::string one_cell(const std::string& camera, const std::string& extra_params) {
    return R"([scene]
name = "one-cell"
ambient = 0.2
)" + camera + R"(
[[light]]
type = "directional"
direction = [-0.3, -1, -0.2]
casts_shadows = false
[[population]]
name = "patch"
kind = "grass"
albedo = [0.1, 0.8, 0.1]
params = { cells_x = 1, cells_z = 1, centre_x = 0.5, centre_z = 0.5, mirror = false, blades = 60, subdivisions = 3, width_min = 0.06, width_max = 0.1, )" +
           extra_params + R"( }
)";
}

const char* kAnyCamera = "[camera]\nposition = [0.5, 0.3, 3]\ntarget = [0.5, 0.2, 0.5]";
// Far along +z with a narrow view: nearly the bake's orthographic view of layer 0.
const char* kFarFront = "[camera]\nposition = [0.5, 0.17, 60]\ntarget = [0.5, 0.17, 0.5]\nfov = 1.1\nnear = 30\nfar = 90";

const Technique& billboard() {
    const Technique* t = TechniqueRegistry::instance().find("grass.billboard");
    REQUIRE(t);
    return *t;
}

ParamSet params(const std::string& orientation = "crossed") {
    return ParamSet::resolve(billboard().params(), {{"resolution", (long long)kBake}, {"orientation", orientation}}, {},
                             {}, "grass.billboard");
}

Bounds prototype_bounds(const Scene& scene) {
    Bounds b;
    for (const Vertex& v : scene.populations[0].family->prototype.vertices) b.extend(v.position);
    return b;
}

// What an orthographic ray through texel (i, j) of `layer` hits: the blade's threshold, or
// BILLBOARD_EMPTY; and a label (the blade) to find edges by.
struct TexelTruth {
    float threshold = shader::BILLBOARD_EMPTY;
    int64_t blade = -1;
};

std::vector<TexelTruth> traced_bake(const Scene& scene, uint32_t layer) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    const FamilyPopulation& family = *scene.populations[0].family;
    const uint32_t per_blade = 2 * (uint32_t(scene.populations[0].params.integer("subdivisions")) + 1);
    const Bounds b = prototype_bounds(scene);
    std::vector<TexelTruth> truth(size_t(kBake) * kBake);
    for (uint32_t j = 0; j < kBake; ++j)
        for (uint32_t i = 0; i < kBake; ++i) {
            const float u = (float(i) + 0.5f) / kBake, v = (float(j) + 0.5f) / kBake;
            const float y = b.max.y * (1.0f - v);
            Ray ray;
            if (layer == 0) {
                ray.origin = {b.min.x + u * (b.max.x - b.min.x), y, b.max.z + 1.0f};
                ray.direction = {0.0f, 0.0f, -1.0f};
            } else {
                ray.origin = {b.max.x + 1.0f, y, b.min.z + u * (b.max.z - b.min.z)};
                ray.direction = {-1.0f, 0.0f, 0.0f};
            }
            const std::optional<PrimaryHit> hit = trace_primary(embree, scene.camera, ray.direction, ray);
            if (!hit) continue;
            const uint32_t blade = (hit->primitive % family.prototype.triangle_count()) / per_blade;
            const uint32_t first_vertex = family.prototype.indices[size_t(blade) * per_blade * 3];
            truth[size_t(j) * kBake + i] = {family.vertex_data[first_vertex].data[0].z, int64_t(blade)};
        }
    return truth;
}

struct BakeAgreement {
    int compared = 0, covered = 0, coverage = 0, threshold = 0;
};

BakeAgreement compare_bake(const Image& baked, const std::vector<TexelTruth>& truth, bool flip_u = false) {
    BakeAgreement a;
    const auto at = [&](int i, int j) -> const TexelTruth& { return truth[size_t(j) * kBake + size_t(i)]; };
    for (int j = 1; j + 1 < int(kBake); ++j)
        for (int i = 1; i + 1 < int(kBake); ++i) {
            bool edge = false;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) edge = edge || at(i + di, j + dj).blade != at(i, j).blade;
            if (edge) continue;
            ++a.compared;
            const float texel = baked.at(flip_u ? int(kBake) - 1 - i : i, j)[3];
            const bool covered = at(i, j).blade >= 0;
            a.covered += covered;
            a.coverage += (texel <= 1.0f) != covered;
            a.threshold += covered && texel <= 1.0f && texel != at(i, j).threshold;
        }
    return a;
}

}  // namespace

TEST_CASE("grass.billboard: the bake shows, texel by texel, the blade Embree's orthographic ray hits and its threshold") {
    const Scene scene = parse_scene(one_cell(kAnyCamera, "density = 1.0"), "one-cell.toml");
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), 64, 48, billboard().graph(params()));
    renderer.render();
    for (uint32_t layer : {0u, 1u}) {
        CAPTURE(layer);
        const Image baked = renderer.read_image("billboard", 0, layer);
        REQUIRE(baked.width == int(kBake));
        const std::vector<TexelTruth> truth = traced_bake(scene, layer);
        const BakeAgreement same = compare_bake(baked, truth);
        CAPTURE(same.compared);
        CAPTURE(same.covered);
        CHECK(same.covered > 500);  // the blades fill a good part of the image
        CHECK(same.coverage == 0);
        CHECK(same.threshold == 0);
        for (float value : baked.pixels) REQUIRE(std::isfinite(value));
        // The comparison sees a flipped image.
        const BakeAgreement flipped = compare_bake(baked, truth, true);
        CAPTURE(flipped.coverage);
        CHECK(flipped.coverage > 200);
    }
}

TEST_CASE("grass.billboard: seen from afar along -z, the crossed quads cover what the reference's rays hit") {
    constexpr uint32_t kWidth = 160, kHeight = 120;
    const Scene scene = parse_scene(one_cell(kFarFront, "density = 1.0"), "one-cell.toml");
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight, billboard().graph(params()));
    renderer.render();
    const Image image = renderer.read_color();
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    const auto hits = test::reference_hits(scene, embree, kWidth, kHeight);
    const uint32_t per_blade = 8;
    const auto label = [&](int x, int y) -> int64_t {
        const auto& h = hits[size_t(y) * kWidth + size_t(x)];
        return h ? int64_t(h->hit.primitive / per_blade) : -1;
    };
    const auto grass = [&](int x, int y) {
        const float* p = image.at(x, y);
        return p[1] > 2.0f * p[0];  // green; the background is black
    };
    int compared = 0, covered = 0, differ = 0;
    for (int y = 1; y + 1 < int(kHeight); ++y)
        for (int x = 1; x + 1 < int(kWidth); ++x) {
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) edge = edge || label(x + dx, y + dy) != label(x, y);
            if (edge) continue;
            ++compared;
            covered += label(x, y) >= 0;
            differ += grass(x, y) != (label(x, y) >= 0);
        }
    CAPTURE(compared);
    CAPTURE(covered);
    CHECK(covered > 400);
    // The bake is orthographic and the camera's view is 1.1 degrees wide: a few pixels may fall
    // on the other side of a blade's edge at the patch's front and back.
    CAPTURE(differ);
    CHECK(differ <= compared / 100);
}

TEST_CASE("grass.billboard: a thinner field cuts the baked blades whose threshold the density does not reach") {
    const Scene dense = parse_scene(one_cell(kFarFront, "density = 1.0"), "one-cell.toml");
    const Scene sparse = parse_scene(one_cell(kFarFront, "density = 0.3"), "one-cell.toml");
    struct Coverage {
        int pixels = 0;                    // the rendered image's grass pixels
        int texels = 0, kept_texels = 0;   // the front image's blade texels, and those at most 0.3
    };
    const auto coverage = [](const Scene& scene) {
        FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), 160, 120, billboard().graph(params()));
        renderer.render();
        Coverage c;
        const Image image = renderer.read_color();
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) c.pixels += image.at(x, y)[1] > 2.0f * image.at(x, y)[0];
        const Image baked = renderer.read_image("billboard", 0, 0);
        for (int y = 0; y < baked.height; ++y)
            for (int x = 0; x < baked.width; ++x) {
                c.texels += baked.at(x, y)[3] <= 1.0f;
                c.kept_texels += baked.at(x, y)[3] <= 0.3f;
            }
        return c;
    };
    const Coverage all = coverage(dense), thinned = coverage(sparse);
    CAPTURE(all.pixels);
    CAPTURE(thinned.pixels);
    // The bake does not depend on the density; the cut does: the front image's share of blade
    // texels whose threshold is at most 0.3 is the share of grass pixels left.
    CHECK(thinned.texels == all.texels);
    const double kept = double(all.kept_texels) / double(all.texels);
    CAPTURE(kept);
    CHECK(kept > 0.1);
    CHECK(kept < 0.7);
    CHECK(double(thinned.pixels) / double(all.pixels) == doctest::Approx(kept).epsilon(0.1));
}

TEST_CASE("grass.billboard: camera-facing quads render a finite image of the field") {
    const Scene scene = parse_scene(one_cell(kAnyCamera, "density = 0.8"), "one-cell.toml");
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), 64, 48,
                           billboard().graph(params("camera_facing")));
    renderer.render();
    const Image image = renderer.read_color();
    int covered = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 4; ++c) REQUIRE(std::isfinite(image.at(x, y)[c]));
            covered += image.at(x, y)[1] > 2.0f * image.at(x, y)[0];
        }
    CHECK(covered > 50);
}
