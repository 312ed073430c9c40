// The reference's pixel-centre visibility (reference/pixel_visibility.hpp): the irradiance-weighted
// visibility of the shadow light at the surface each pixel centre sees, against closed forms;
// its masks hold still when the light sample count changes; it is cached under its own key and
// does not depend on an experiment's [reference] settings.
#include "config/scene_config.hpp"
#include "core/pixel_visibility.hpp"
#include "reference/embree_scene.hpp"
#include "reference/pixel_visibility.hpp"
#include "reference/reference_cache.hpp"
#include "run/reference_provider.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"
#include "support/closed_forms.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace canopy;
namespace pv = canopy::pixel_visibility;

namespace {

Object plane(glm::vec2 size, glm::vec3 translate) {
    Object object;
    object.name = "plane";
    object.shape = ShapeType::plane;
    object.plane_size = size;
    object.instances = {Transform{}};
    object.instances[0].translate = translate;
    return object;
}

// The ground y = 0 seen straight down from height 10 (image x along world +x, 2.4 units across
// an image of `aspect` = width / height), the half-plane x < 0 at height 1 as occluder (behind the
// near plane, so only its shadow is seen), and `light`.
Scene edge_scene(const Light& light, double aspect) {
    Scene scene;
    scene.name = "edge";
    scene.camera.position = {0.0f, 10.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.near_plane = 9.5f;
    scene.camera.fov_y_degrees = float(2.0 * std::atan(1.2 / aspect / 10.0) * 180.0 / 3.14159265358979);
    scene.objects.push_back(plane({20.0f, 20.0f}, glm::vec3(0.0f)));
    scene.objects.push_back(plane({40.0f, 40.0f}, {-20.0f, 1.0f, 0.0f}));
    scene.lights.push_back(light);
    return scene;
}

Light rect_light(glm::vec3 center, glm::vec2 size) {
    Light light;
    light.type = LightType::rect;
    light.position = center;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.rect_up_hint = {0.0f, 0.0f, 1.0f};
    light.rect_size = size;
    light.intensity = 4.0f;
    return light;
}

PixelVisibilityRender render(const Scene& scene, int width, int height, int light_samples = kPixelVisibilitySamples) {
    const EmbreeScene embree(scene, build_scene_meshes(scene));
    PixelVisibilitySettings settings;
    settings.light_samples = light_samples;
    return render_pixel_visibility(scene, embree, width, height, settings);
}

// The ground x a pixel centre of the edge scene's image sees.
double ground_x(const Scene& scene, int width, int height, int x, int y) {
    const Ray ray = primary_ray(scene.camera, width, height, float(x) + 0.5f, float(y) + 0.5f);
    return ray.origin.x - ray.origin.y / ray.direction.y * ray.direction.x;
}

enum class Class { umbra, penumbra, lit };
Class classify(float v) { return v <= 1e-3f ? Class::umbra : v >= 1.0f - 1e-3f ? Class::lit : Class::penumbra; }

}  // namespace

TEST_CASE("pixel-centre visibility of a straight edge under a rect light: the lit share of E, exactly") {
    // From ground point x the light (width w along x, at height 2, centred over the edge) is seen
    // where the segment to it passes height 1 at x >= 0, i.e. for light points x' >= -x. V is the
    // irradiance of that part of the rectangle over the whole's (Lambert's polygon formula), a
    // near-linear ramp from x = -w/2 (umbra) to w/2 (lit).
    const float w = 1.2f, h = 0.4f;
    const int width = 160, height = 8;
    const Scene scene = edge_scene(rect_light({0.0f, 2.0f, 0.0f}, {w, h}), double(width) / height);
    const Image image = render(scene, width, height).visibility;
    const auto irradiance = [&](double x, double x0) {
        const std::vector<glm::dvec3> corners = {{x0, 2.0, -0.5 * h}, {0.5 * w, 2.0, -0.5 * h}, {0.5 * w, 2.0, 0.5 * h},
                                                 {x0, 2.0, 0.5 * h}};
        return test::polygon_irradiance(corners, {x, 0.0, 0.0}, {0.0, 1.0, 0.0}, 1.0);
    };
    int penumbra = 0;
    double largest_error = 0.0, squared_error = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double gx = ground_x(scene, width, height, x, y);
            const double x0 = std::max(-gx, -0.5 * w);
            const double exact = x0 >= 0.5 * w ? 0.0 : irradiance(gx, x0) / irradiance(gx, -0.5 * w);
            const float v = image.at(x, y)[pv::kVisibility];
            INFO("pixel (" << x << ", " << y << "), ground x " << gx << ": V " << v << ", exact " << exact);
            REQUIRE(pv::has_surface(image, x, y));
            // 32 x 32 strata, the weights (cos cos / d^2) varying by ~15 % over the light: a few 1e-3.
            CHECK(std::abs(v - exact) <= 0.01);
            largest_error = std::max(largest_error, std::abs(v - exact));
            if (exact == 0.0) CHECK(v == 0.0f);  // umbra: no sample sees the light
            if (exact == 1.0) CHECK(v == 1.0f);
            const bool in_penumbra = exact > 0.0 && exact < 1.0;
            penumbra += in_penumbra;
            if (in_penumbra) squared_error += (v - exact) * (v - exact);
        }
    const double rms = std::sqrt(squared_error / penumbra);
    MESSAGE("over " << penumbra << " penumbra pixels: RMS |V - exact| " << rms << ", largest " << largest_error);
    CHECK(penumbra > 40 * height);
    // Far below the visibility errors of the techniques (0.02 and more on the committed scenes).
    CHECK(rms < 3e-3);
}

TEST_CASE("pixel-centre visibility: view depth, background, light that does not reach, point lights") {
    const int width = 64, height = 8;
    Scene scene = edge_scene(rect_light({0.0f, 2.0f, 0.0f}, {1.0f, 1.0f}), double(width) / height);
    scene.objects[0].plane_size = {2.0f, 20.0f};  // the ground ends at x = +-1: background beyond
    const Image image = render(scene, width, height, 64).visibility;
    for (int x = 0; x < width; ++x) {
        const double gx = ground_x(scene, width, height, x, 4);
        if (std::abs(std::abs(gx) - 1.0) < 0.05) continue;  // the ground's edge
        CAPTURE(gx);
        if (std::abs(gx) > 1.0) {
            CHECK_FALSE(pv::has_surface(image, x, 4));
            CHECK(image.at(x, 4)[pv::kVisibility] == pv::kNotLit);
            CHECK(image.at(x, 4)[pv::kViewDepth] == 0.0f);
        } else {
            CHECK(pv::has_surface(image, x, 4));
            CHECK(image.at(x, 4)[pv::kViewDepth] == doctest::Approx(10.0).epsilon(1e-6));  // along the view axis
        }
    }

    // A light below the ground reaches nothing the camera sees: every V is kNotLit, the surfaces stay.
    Scene below = scene;
    below.lights[0] = rect_light({0.0f, -2.0f, 0.0f}, {1.0f, 1.0f});
    below.lights[0].direction = {0.0f, 1.0f, 0.0f};
    const Image unlit = render(below, width, height, 64).visibility;
    CHECK(pv::has_surface(unlit, width / 2, 4));
    for (int x = 0; x < width; ++x) CHECK(unlit.at(x, 4)[pv::kVisibility] == pv::kNotLit);

    // A directional light: 0 or 1, the edge's shadow where the occluder's plane projects it.
    Light sun;
    sun.type = LightType::directional;
    sun.direction = glm::normalize(glm::vec3(-0.5f, -1.0f, 0.0f));  // shadow edge at x = -0.5
    const Scene sunny = edge_scene(sun, double(width) / height);
    const Image hard = render(sunny, width, height).visibility;
    for (int x = 0; x < width; ++x) {
        const double gx = ground_x(sunny, width, height, x, 4);
        if (std::abs(gx + 0.5) < 0.03) continue;
        CAPTURE(gx);
        CHECK(hard.at(x, 4)[pv::kVisibility] == (gx < -0.5 ? 0.0f : 1.0f));
    }

    // A spot light: pixels outside its cone are not lit; inside, the hard shadow.
    Light spot;
    spot.type = LightType::spot;
    spot.position = {0.5f, 3.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.spot_angle_degrees = 10.0f;  // a cone of radius ~0.5 on the ground around x = 0.5
    spot.intensity = 10.0f;
    const Scene spotlit = edge_scene(spot, double(width) / height);
    const Image cone = render(spotlit, width, height).visibility;
    for (int x = 0; x < width; ++x) {
        const double gx = ground_x(spotlit, width, height, x, 4);
        CAPTURE(gx);
        if (std::abs(gx - 0.5) > 0.6) CHECK(cone.at(x, 4)[pv::kVisibility] == pv::kNotLit);
        if (std::abs(gx - 0.5) < 0.3) CHECK(cone.at(x, 4)[pv::kVisibility] == 1.0f);
    }
}

TEST_CASE("pixel-centre masks hold still when the light sample count changes") {
    // The umbra, penumbra and lit classes the shadow metrics use, from 256 and from 1024 light
    // samples on the spheres scene: they differ only where V lies within a sample's weight of a
    // class boundary.
    const Scene scene = load_scene(std::string(CANOPY_SOURCE_DIR) + "/configs/scenes/spheres.toml");
    const int width = 160, height = 90;
    const Image coarse = render(scene, width, height, 256).visibility;
    const Image fine = render(scene, width, height, 1024).visibility;
    long long reached = 0, differ = 0, penumbra = 0, umbra = 0;
    double largest = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!pv::is_lit(coarse, x, y) && !pv::is_lit(fine, x, y)) continue;
            ++reached;
            if (pv::is_lit(coarse, x, y) != pv::is_lit(fine, x, y)) {  // the light's reach itself moved
                ++differ;
                continue;
            }
            const float a = coarse.at(x, y)[pv::kVisibility], b = fine.at(x, y)[pv::kVisibility];
            differ += classify(a) != classify(b);
            penumbra += classify(b) == Class::penumbra;
            umbra += classify(b) == Class::umbra;
            largest = std::max(largest, double(std::abs(a - b)));
        }
    MESSAGE("classes differ at " << differ << " of " << reached << " pixels the light reaches (" << penumbra
                                 << " penumbra, " << umbra << " umbra); largest |V_256 - V_1024| " << largest);
    REQUIRE(penumbra > 100);
    REQUIRE(umbra > 20);
    CHECK(differ <= 0.002 * reached);
    CHECK(largest < 0.05);  // stratified: far below the 1/sqrt(256) of independent samples' noise
}

TEST_CASE("pixel-centre visibility: independent of the thread count; cached under its own key") {
    const Scene scene = edge_scene(rect_light({0.0f, 2.0f, 0.0f}, {1.0f, 0.5f}), 40.0 / 6.0);
    const auto meshes = build_scene_meshes(scene);
    const EmbreeScene embree(scene, meshes);
    PixelVisibilitySettings settings;
    settings.light_samples = 64;
    settings.threads = 1;
    const PixelVisibilityRender one = render_pixel_visibility(scene, embree, 40, 6, settings);
    settings.threads = 2;
    const PixelVisibilityRender two = render_pixel_visibility(scene, embree, 40, 6, settings);
    CHECK(one.visibility.pixels == two.visibility.pixels);
    CHECK(one.shadow_rays > 0);

    const std::string key = pixel_visibility_cache_key(scene, meshes, 40, 6, settings);
    const test::TempFolder folder;
    CHECK_FALSE(load_cached_pixel_visibility(folder.path(), key));
    store_pixel_visibility(folder.path(), key, one);
    const auto loaded = load_cached_pixel_visibility(folder.path(), key);
    REQUIRE(loaded);
    CHECK(loaded->visibility.pixels == one.visibility.pixels);
    CHECK(loaded->shadow_rays == one.shadow_rays);
    // What changes the image changes the key; the thread count does not.
    PixelVisibilitySettings other = settings;
    other.threads = 1;
    CHECK(pixel_visibility_cache_key(scene, meshes, 40, 6, other) == key);
    other.light_samples = 128;
    CHECK(pixel_visibility_cache_key(scene, meshes, 40, 6, other) != key);
    other = settings;
    other.position_in_pixel_x = 0.25f;
    CHECK(pixel_visibility_cache_key(scene, meshes, 40, 6, other) != key);
    CHECK(pixel_visibility_cache_key(scene, meshes, 41, 6, settings) != key);
    Scene moved = scene;
    moved.objects[1].casts_shadows = false;
    CHECK(pixel_visibility_cache_key(moved, meshes, 40, 6, settings) != key);
}

TEST_CASE("the reference provider's pixel visibility is the same for any [reference] sample counts") {
    // An experiment's light_samples, pixel_samples and seed change the anti-aliased reference,
    // never the pixel-centre visibility the masks and the isolated error come from.
    const Scene scene = edge_scene(rect_light({0.0f, 2.0f, 0.0f}, {1.0f, 0.5f}), 6.0);
    const auto meshes = build_scene_meshes(scene);
    const test::TempFolder folder;
    ReferenceProvider coarse(folder.path() / "cache", ReferenceSettings{4, 1, 7, 0});
    ReferenceProvider fine(folder.path() / "cache", ReferenceSettings{16, 2, 1, 0});
    const ReferenceEntry& a = coarse.get(scene, meshes, 24, 4);
    const ReferenceEntry& b = fine.get(scene, meshes, 24, 4);
    CHECK(a.key != b.key);
    CHECK(a.pixel_visibility_key == b.pixel_visibility_key);
    CHECK_FALSE(a.pixel_visibility_from_cache);
    CHECK(b.pixel_visibility_from_cache);  // rendered once, then shared
    CHECK(a.pixel_visibility.visibility.pixels == b.pixel_visibility.visibility.pixels);
    CHECK(coarse.pixel_visibility_settings().light_samples == kPixelVisibilitySamples);
}
