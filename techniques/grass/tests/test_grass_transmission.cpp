// Boulanger's transmission term (eq 4.1's gamma; the grass kind's `transmission`): blades lit from
// behind pass gamma times the far side's irradiance to the side seen, in every representation and
// in the reference alike. On a patch lit from behind, the blades' radiance in the raster (blades)
// and the reference agree at gamma 0 and at gamma 0.6, and gamma 0.6 is brighter by what the
// model says; the image slice (shaded from its baked normal) and the ground agree with gamma's
// effect too. A representation that ignores gamma, or a reference that adds it to the lit side,
// fails a check here.
#include "support/bake_truth.hpp"

#include "core/registry.hpp"
#include "reference/embree_scene.hpp"
#include "reference/reference_renderer.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "support/reference_hits.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>

using namespace canopy;

namespace {

constexpr int kWidth = 160, kHeight = 100;

// One cell seen from the front, the sun behind the patch (travelling towards the camera), so the
// blades' faces the camera sees are mostly lit from behind.
Scene back_lit(double transmission) {
    Scene scene = grass::test::one_cell_scene(
        "[camera]\nposition = [0.5, 0.35, 2.2]\ntarget = [0.5, 0.12, 0.5]\nfov = 30",
        "density = 1.0, transmission = " + std::to_string(transmission));
    scene.lights.at(0).direction = glm::normalize(glm::vec3(0.1f, -0.6f, 1.0f));
    return scene;
}

// The mean green over pixels where the reference's primary ray hits a blade and the raster shows
// grass, away from blade edges (one pixel).
struct Means {
    double raster = 0, reference = 0;
    int pixels = 0;
};

Means blade_means(const Scene& scene, const std::string& technique, const std::map<std::string, ParamValue>& params) {
    const Image raster = test::render_technique(scene, technique, params, kWidth, kHeight);
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    ReferenceSettings settings;
    settings.pixel_samples = 1;
    settings.light_samples = 1;
    const ReferenceImages reference = render_reference(scene, embree, kWidth, kHeight, settings);
    const auto hits = test::reference_hits(scene, embree, kWidth, kHeight);
    const auto label = [&](int x, int y) -> int64_t {
        const auto& h = hits[size_t(y) * kWidth + size_t(x)];
        return h && h->what.population >= 0 ? int64_t(h->hit.primitive / 8) : -1;  // 8 triangles a blade
    };
    Means m;
    for (int y = 1; y + 1 < kHeight; ++y)
        for (int x = 1; x + 1 < kWidth; ++x) {
            const int64_t blade = label(x, y);
            if (blade < 0 || !grass::test::shows_grass(raster.at(x, y))) continue;
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) edge = edge || label(x + dx, y + dy) != blade;
            if (edge) continue;
            m.raster += raster.at(x, y)[1];
            m.reference += reference.radiance.at(x, y)[1];
            ++m.pixels;
        }
    if (m.pixels > 0) {
        m.raster /= m.pixels;
        m.reference /= m.pixels;
    }
    return m;
}

}  // namespace

TEST_CASE("grass transmission: blades lit from behind, the raster and the reference add the same gamma term") {
    const std::map<std::string, ParamValue> blades{{"samples", 1LL}, {"coverage", std::string("alpha_test")}};
    const Means opaque = blade_means(back_lit(0.0), "grass.geometry", blades);
    const Means thin = blade_means(back_lit(0.6), "grass.geometry", blades);
    CAPTURE(opaque.pixels);
    CAPTURE(opaque.raster);
    CAPTURE(opaque.reference);
    CAPTURE(thin.raster);
    CAPTURE(thin.reference);
    CHECK(opaque.pixels > 300);
    CHECK(thin.pixels > 300);
    // The same shading model on both sides (vertex-interpolated normals agree to a few %).
    CHECK(opaque.raster == doctest::Approx(opaque.reference).epsilon(0.05));
    CHECK(thin.raster == doctest::Approx(thin.reference).epsilon(0.05));
    // Lit from behind, gamma brightens the blades well beyond the few front-lit ones.
    CHECK(thin.reference > 1.5 * opaque.reference);
    CHECK(thin.raster > 1.5 * opaque.raster);
}

TEST_CASE("grass transmission: the image-based representations and the ground follow gamma as the blades do") {
    for (const std::string technique : {"grass.image", "grass.volume", "grass.billboard", "grass.slices"}) {
        CAPTURE(technique);
        std::map<std::string, ParamValue> params;
        for (int macro : {0, 1}) {
            const bool has_macro_cells = technique == "grass.image" || technique == "grass.volume";
            if (!has_macro_cells && macro == 1) continue;
            if (has_macro_cells) params["macro_cells"] = (long long)macro;
            CAPTURE(macro);
            const Image opaque = test::render_technique(back_lit(0.0), technique, params, kWidth, kHeight);
            const Image thin = test::render_technique(back_lit(0.6), technique, params, kWidth, kHeight);
            double sum_opaque = 0, sum_thin = 0;
            int pixels = 0;
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x)
                    if (grass::test::shows_grass(opaque.at(x, y)) && grass::test::shows_grass(thin.at(x, y))) {
                        sum_opaque += opaque.at(x, y)[1];
                        sum_thin += thin.at(x, y)[1];
                        ++pixels;
                    }
            CAPTURE(pixels);
            CHECK(pixels > 100);
            CHECK(sum_thin > 1.3 * sum_opaque);
        }
    }
}
