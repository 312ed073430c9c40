// The raster and the reference sample the same points: the surface the rasteriser draws at a
// pixel is the one the reference's pixel-centre ray hits, at the same depth. This is what lets
// the technique-isolated error compare a technique's visibility with the truth pixel by pixel;
// a half-pixel offset between the two conventions must show.
#include "config/scene_config.hpp"
#include "core/pixel_visibility.hpp"
#include "reference/embree_scene.hpp"
#include "reference/pixel_visibility.hpp"
#include "render/frame_renderer.hpp"
#include "support/test_gpu.hpp"
#include "support/tiny_scene.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace canopy;
namespace pv = canopy::pixel_visibility;

namespace {

struct Agreement {
    long long coverage_differs = 0;  // pixels where one side sees a surface and the other does not
    long long interior = 0;          // pixels whose centre and 4-neighbours see a surface on both sides
    long long depth_differs = 0;     // interior pixels whose view depths differ by more than 1e-4 (relative)
    double median_depth_error = 0;   // relative, over the interior pixels
    long long lit_differs = 0;       // interior pixels lit on one side only (the light at its centre vs any sample)
    long long misaligned() const { return coverage_differs + depth_differs; }
};

bool surface_with_neighbours(const Image& image, int x, int y) {
    if (x == 0 || y == 0 || x + 1 == image.width || y + 1 == image.height) return false;
    for (auto [dx, dy] : {std::pair{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}})
        if (!pv::has_surface(image, x + dx, y + dy)) return false;
    return true;
}

Agreement agreement(const Image& raster, const Image& reference) {
    Agreement a;
    std::vector<double> errors;
    for (int y = 0; y < raster.height; ++y)
        for (int x = 0; x < raster.width; ++x) {
            a.coverage_differs += pv::has_surface(raster, x, y) != pv::has_surface(reference, x, y);
            if (!surface_with_neighbours(raster, x, y) || !surface_with_neighbours(reference, x, y)) continue;
            ++a.interior;
            const double depth = reference.at(x, y)[pv::kViewDepth];
            const double error = std::abs(raster.at(x, y)[pv::kViewDepth] - depth) / depth;
            errors.push_back(error);
            a.depth_differs += error > 1e-4;
            a.lit_differs += pv::is_lit(raster, x, y) != pv::is_lit(reference, x, y);
        }
    if (!errors.empty()) {
        std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(errors.size() / 2), errors.end());
        a.median_depth_error = errors[errors.size() / 2];
    }
    return a;
}

struct Renders {
    Image raster, centres, shifted_right, shifted_down;
};

Renders render_both(const Scene& scene, int width, int height) {
    const auto meshes = build_scene_meshes(scene);
    FrameRenderer renderer(test::gpu(), scene, meshes, uint32_t(width), uint32_t(height),
                           test::technique_graph("shadow.hard"));
    renderer.render();
    Renders r;
    r.raster = renderer.read_pixel_visibility();
    const EmbreeScene embree(scene, meshes);
    PixelVisibilitySettings settings;
    settings.light_samples = 16;  // visibility is not what this test looks at
    r.centres = render_pixel_visibility(scene, embree, width, height, settings).visibility;
    settings.position_in_pixel_x = 1.0f;  // half a pixel to the right
    r.shifted_right = render_pixel_visibility(scene, embree, width, height, settings).visibility;
    settings.position_in_pixel_x = 0.5f;
    settings.position_in_pixel_y = 1.0f;  // half a pixel down
    r.shifted_down = render_pixel_visibility(scene, embree, width, height, settings).visibility;
    return r;
}

void check_alignment(const Scene& scene, int width, int height) {
    const Renders r = render_both(scene, width, height);
    const double pixels = double(width) * height;
    const Agreement centres = agreement(r.raster, r.centres);
    INFO("centres: coverage differs at ", centres.coverage_differs, ", depth at ", centres.depth_differs, " of ",
         centres.interior, " interior pixels, median relative depth error ", centres.median_depth_error,
         ", lit differs at ", centres.lit_differs);
    REQUIRE(centres.interior > 0.3 * pixels);
    // Coverage differs only where a pixel centre lies within rounding of an edge.
    CHECK(centres.coverage_differs <= 0.002 * pixels + 2);
    // Both sides see the same point: depths agree to the precision of the stored depth (a float
    // near 1: a few 1e-6 of the view depth here), everywhere inside surfaces.
    CHECK(centres.median_depth_error < 2e-5);
    CHECK(centres.depth_differs <= 0.001 * centres.interior);

    for (const auto& [what, shifted] : {std::pair{"half a pixel right", &r.shifted_right},
                                        std::pair{"half a pixel down", &r.shifted_down}}) {
        const Agreement a = agreement(r.raster, *shifted);
        INFO(what, ": coverage differs at ", a.coverage_differs, ", depth at ", a.depth_differs, " of ", a.interior,
             " interior pixels, median relative depth error ", a.median_depth_error);
        // Half a pixel moves every edge across pixel centres and changes the depth of every
        // surface whose depth varies along the shift (a floor's only vertically).
        CHECK(a.misaligned() > 10 * centres.misaligned() + 0.003 * pixels);
    }
    const Agreement down = agreement(r.raster, r.shifted_down);
    CHECK(down.depth_differs > 0.5 * down.interior);  // the floor recedes row by row
}

}  // namespace

TEST_CASE("raster and reference pixel centres coincide: the tiny scene, every pixel's depth") {
    check_alignment(test::tiny_scene(), 96, 64);
}

TEST_CASE("raster and reference pixel centres coincide: the spheres scene at an odd size") {
    // An odd width and height: a convention that rounds the centre differently would show here.
    const Scene scene = load_scene(std::string(CANOPY_SOURCE_DIR) + "/configs/scenes/spheres.toml");
    check_alignment(scene, 161, 91);
}
