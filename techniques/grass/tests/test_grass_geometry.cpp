// grass.geometry against the Embree reference: at every pixel centre away from the edges of
// what the reference sees (a blade against another, or against the ground), the raster image
// shows grass exactly where the reference's primary ray hits a blade, at the same depth. This
// pins the blades' placement, the cells' mirrors, the vertex shader's thinning and the alpha
// test's outline together; the reference built with another density, without mirrors or with
// the field shifted by about 2 pixels must disagree (the test shows it can fail).
#include "config/scene_config.hpp"
#include "core/pixel_visibility.hpp"
#include "core/registry.hpp"
#include "reference/embree_scene.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "support/reference_hits.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace canopy;

namespace {

constexpr uint32_t kWidth = 200, kHeight = 150;

// Few, wide blades on 3 x 2 cells seen obliquely from above, so blades are several pixels wide
// and stand over one another, mirrored cells side by side.
std::string lawn(const std::string& params) {
    return R"([scene]
name = "lawn-top"
ambient = 0.2
[camera]
position = [0.3, 1.3, 2.2]
target = [0.0, 0.0, 0.0]
fov = 50
near = 0.1
far = 20
[[light]]
type = "directional"
direction = [-0.3, -1, -0.2]
casts_shadows = false
[[object]]
name = "ground"
shape = "plane"
size = [8, 8]
albedo = [0.6, 0.3, 0.1]
[[population]]
name = "lawn"
kind = "grass"
albedo = [0.1, 0.8, 0.1]
params = { cells_x = 3, cells_z = 2, blades = 40, subdivisions = 3, width_min = 0.06, width_max = 0.1, )" +
           params + R"( }
)";
}

Scene lawn_scene(const std::string& params = "density = 0.6") { return parse_scene(lawn(params), "lawn-top.toml"); }

// The lawn on hills: a heightfield one grid quad a cell under it (grass_terrain.h), `ground_keys`
// shaping it; `on_terrain` false keeps the blades on flat ground (the heightfield still drawn).
Scene hilly_lawn_scene(const std::string& ground_keys, bool on_terrain = true) {
    std::string text = lawn("density = 0.6");
    const auto replace = [&](const std::string& from, const std::string& to) {
        const size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
    };
    replace("shape = \"plane\"\nsize = [8, 8]\n", "shape = \"heightfield\"\nsize = [3, 2]\nvertices = [4, 3]\n" + ground_keys);
    if (on_terrain) replace("kind = \"grass\"\n", "kind = \"grass\"\nterrain = \"ground\"\n");
    return parse_scene(text, "lawn-hills.toml");
}

struct Raster {
    Image color, visibility;
};

Raster render(const Scene& scene, const std::string& coverage = "alpha_test", long long samples = 1) {
    const Technique* technique = TechniqueRegistry::instance().find("grass.geometry");
    REQUIRE(technique);
    const ParamSet params = ParamSet::resolve(technique->params(), {{"coverage", coverage}, {"samples", samples}}, {}, {},
                                              technique->name());
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight, technique->graph(params));
    renderer.render();
    FrameRenderer::ColorAndVisibility images = renderer.read_color_and_pixel_visibility();
    return {std::move(images.color), std::move(images.visibility)};
}

bool shows_grass(const float* rgb) { return rgb[1] > 2.0f * rgb[0]; }  // green; the ground is brown

struct ReferencePixel {
    int64_t label = -1;  // -1 background; else geometry, and for the field its copy and blade
    bool grass = false;
    float view_depth = 0.0f;
};

std::vector<ReferencePixel> reference_pixels(const Scene& scene) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    const uint32_t per_blade = 2 * (uint32_t(scene.populations[0].params.integer("subdivisions")) + 1);
    std::vector<ReferencePixel> pixels;
    for (const std::optional<test::ReferenceHit>& hit : test::reference_hits(scene, embree, kWidth, kHeight)) {
        ReferencePixel& p = pixels.emplace_back();
        if (!hit) continue;
        p.grass = hit->what.population >= 0;
        p.view_depth = hit->hit.view_depth;
        p.label = int64_t(hit->hit.geometry) << 40;
        if (p.grass) {
            const uint32_t copy = hit->hit.primitive / hit->what.prototype_triangles;
            const uint32_t blade = (hit->hit.primitive % hit->what.prototype_triangles) / per_blade;
            p.label |= (int64_t(copy) << 20) | int64_t(blade);
        }
    }
    return pixels;
}

struct Disagreement {
    int compared = 0, coverage = 0, depth = 0, grass_pixels = 0;
};

Disagreement compare(const Raster& raster, const std::vector<ReferencePixel>& reference) {
    namespace pv = pixel_visibility;
    Disagreement d;
    const auto at = [&](int x, int y) -> const ReferencePixel& { return reference[size_t(y) * kWidth + size_t(x)]; };
    for (int y = 1; y + 1 < int(kHeight); ++y)
        for (int x = 1; x + 1 < int(kWidth); ++x) {
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) edge = edge || at(x + dx, y + dy).label != at(x, y).label;
            if (edge) continue;
            ++d.compared;
            const ReferencePixel& r = at(x, y);
            d.grass_pixels += r.grass;
            d.coverage += shows_grass(raster.color.at(x, y)) != r.grass;
            const float* v = raster.visibility.at(x, y);
            if (r.label >= 0 && v[pv::kSurface] >= 0.5f && std::abs(v[pv::kViewDepth] - r.view_depth) > 2e-3f * r.view_depth)
                ++d.depth;
        }
    return d;
}

}  // namespace

TEST_CASE("grass.geometry: the blades cover what the reference's primary rays hit, at its depths") {
    const Scene scene = lawn_scene();
    const Raster raster = render(scene);
    const Disagreement same = compare(raster, reference_pixels(scene));
    CAPTURE(same.compared);
    CAPTURE(same.grass_pixels);
    CHECK(same.compared > int(kWidth * kHeight) / 3);
    CHECK(same.grass_pixels > 1000);
    CHECK(same.coverage == 0);
    CHECK(same.depth == 0);

    SUBCASE("the reference at another density") {
        const Disagreement d = compare(raster, reference_pixels(lawn_scene("density = 0.8")));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 100);
    }
    SUBCASE("the reference without mirrors") {
        const Disagreement d = compare(raster, reference_pixels(lawn_scene("density = 0.6, mirror = false")));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 300);
    }
    SUBCASE("the reference's field shifted by about 2 pixels") {
        const Disagreement d = compare(raster, reference_pixels(lawn_scene("density = 0.6, centre_x = 0.05")));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 100);
    }
}

TEST_CASE("grass.geometry on a terrain: each blade stands on the ground under its root, as in the reference") {
    const std::string hills = "height_scale = 0.5\nperiods = 1\nseed = 3\n";
    const Scene scene = hilly_lawn_scene(hills);
    const Raster raster = render(scene);
    const Disagreement same = compare(raster, reference_pixels(scene));
    CAPTURE(same.compared);
    CAPTURE(same.grass_pixels);
    CHECK(same.grass_pixels > 1000);
    CHECK(same.coverage == 0);
    CHECK(same.depth == 0);

    SUBCASE("the reference's blades on flat ground") {
        const Disagreement d = compare(raster, reference_pixels(hilly_lawn_scene(hills, false)));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 300);
    }
    SUBCASE("the reference on other hills") {
        const Disagreement d = compare(raster, reference_pixels(hilly_lawn_scene("height_scale = 0.5\nperiods = 1\nseed = 4\n")));
        CAPTURE(d.coverage);
        CHECK(d.coverage > 300);
    }
}

TEST_CASE("grass.geometry: alpha-to-coverage at 4x covers what the alpha test covers, off the blades' edges") {
    const Scene scene = lawn_scene();
    const Raster hard = render(scene);
    const Raster smooth = render(scene, "alpha_to_coverage", 4);
    const std::vector<ReferencePixel> reference = reference_pixels(scene);
    int compared = 0, differ = 0;
    for (int y = 1; y + 1 < int(kHeight); ++y)
        for (int x = 1; x + 1 < int(kWidth); ++x) {
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    edge = edge || reference[size_t(y + dy) * kWidth + size_t(x + dx)].label !=
                                       reference[size_t(y) * kWidth + size_t(x)].label;
            if (edge) continue;
            ++compared;
            differ += shows_grass(hard.color.at(x, y)) != shows_grass(smooth.color.at(x, y));
        }
    CAPTURE(compared);
    CHECK(differ <= compared / 200);
    for (const float value : smooth.color.pixels) REQUIRE(std::isfinite(value));
}
