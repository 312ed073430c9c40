// The Embree reference renderer: closed-form irradiance and visibility, camera convention,
// shading, cache keys and files, the alpha-test hook, and error reporting.
#include "core/error.hpp"
#include "reference/embree_scene.hpp"
#include "reference/light_integrator.hpp"
#include "reference/light_sampling.hpp"
#include "reference/reference_cache.hpp"
#include "reference/reference_renderer.hpp"
#include "reference/shadow_ray_benchmark.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"
#include "shading.h"
#include "support/closed_forms.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numeric>

using namespace canopy;
using test::polygon_irradiance;

namespace {

constexpr double kPi = 3.14159265358979323846;

Object plane_object(const std::string& name, glm::vec2 size, glm::vec3 translate, glm::vec3 albedo = glm::vec3(0.5f)) {
    Object object;
    object.name = name;
    object.shape = ShapeType::plane;
    object.plane_size = size;
    object.instances = {Transform{}};
    object.instances[0].translate = translate;
    object.material.albedo = albedo;
    object.where = {"test.toml", 10};
    return object;
}

Object sphere_object(const std::string& name, float radius, glm::vec3 center, int segments = 32) {
    Object object;
    object.name = name;
    object.shape = ShapeType::sphere;
    object.radius = radius;
    object.segments = segments;
    object.instances = {Transform{}};
    object.instances[0].translate = center;
    object.where = {"test.toml", 20};
    return object;
}

// A rect light facing down (-y) centred at `center`; width along right = -x, height along up = +z.
Light downward_rect_light(glm::vec3 center, glm::vec2 size, float intensity) {
    Light light;
    light.type = LightType::rect;
    light.position = center;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.rect_up_hint = {0.0f, 0.0f, 1.0f};
    light.rect_size = size;
    light.intensity = intensity;
    light.where = {"test.toml", 30};
    return light;
}

Light sphere_light(glm::vec3 center, float radius, float intensity) {
    Light light;
    light.type = LightType::sphere;
    light.position = center;
    light.sphere_radius = radius;
    light.intensity = intensity;
    light.where = {"test.toml", 40};
    return light;
}

// A disk in the xz plane (normal +y), a fan of `segments` triangles.
TriangleMesh disk_mesh(float radius, int segments) {
    TriangleMesh mesh;
    mesh.vertices.push_back({glm::vec3(0.0f), glm::vec3(0, 1, 0)});
    for (int i = 0; i < segments; ++i) {
        const double phi = 2.0 * kPi * i / segments;
        mesh.vertices.push_back({glm::vec3(float(radius * std::cos(phi)), 0.0f, float(radius * std::sin(phi))),
                                 glm::vec3(0, 1, 0)});
    }
    for (int i = 0; i < segments; ++i)
        mesh.indices.insert(mesh.indices.end(), {0u, uint32_t(1 + (i + 1) % segments), uint32_t(1 + i)});
    return mesh;
}

// Many independent estimates of one light at one point: their mean, the spread of the mean
// measured across estimates, and the spread the estimator itself predicts.
struct PointEstimate {
    double irradiance = 0, irradiance_sigma = 0, predicted_sigma = 0;
    double visible = 0, visible_sigma = 0;
};

PointEstimate estimate_at(const EmbreeScene& embree, const PreparedLight& light, glm::vec3 p, glm::vec3 n, int repeats) {
    EmbreeShadowTracer tracer(embree.shadow_scene());
    SurfacePoint surface;
    surface.position = p;
    surface.normal = glm::normalize(n);
    surface.origin = p + shadow_ray_offset(p, 1.0f, embree.extent()) * surface.normal;
    std::vector<double> irradiance, visible;
    double predicted_variance = 0;
    for (int k = 0; k < repeats; ++k) {
        const LightEstimate e = integrate_light(light, surface, random_key(77, uint64_t(k)), true, tracer);
        irradiance.push_back(e.irradiance.r);
        visible.push_back(e.visible_fraction);
        predicted_variance += e.variance.r;
    }
    const auto mean_and_sigma = [&](const std::vector<double>& values, double& mean, double& sigma) {
        mean = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
        double squares = 0;
        for (double v : values) squares += (v - mean) * (v - mean);
        sigma = std::sqrt(squares / double(values.size() - 1) / double(values.size()));
    };
    PointEstimate result;
    mean_and_sigma(irradiance, result.irradiance, result.irradiance_sigma);
    mean_and_sigma(visible, result.visible, result.visible_sigma);
    result.predicted_sigma = std::sqrt(predicted_variance) / repeats;
    return result;
}

// |mean - exact| within 4 sigma of the spread measured across independent estimates (plus float
// rounding), within a loose relative bound, and the estimator's own variance not too optimistic.
void check_estimate(const PointEstimate& e, double exact, const std::string& what) {
    INFO(what << ": estimate " << e.irradiance << " +- " << e.irradiance_sigma << " (predicted "
              << e.predicted_sigma << "), exact " << exact);
    CHECK(std::abs(e.irradiance - exact) <= 4.0 * e.irradiance_sigma + 2e-5 * exact);
    CHECK(std::abs(e.irradiance - exact) <= 0.01 * exact);
    CHECK(e.predicted_sigma >= 0.5 * e.irradiance_sigma);
}

Scene camera_scene() {
    Scene scene;
    scene.name = "test";
    scene.camera.position = {0.0f, 0.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, -1.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.fov_y_degrees = 40.0f;
    scene.ambient = glm::vec3(0.0f);
    return scene;
}

// Ground plane, a few spheres and one area light: the kind of scene references are made of.
Scene spheres_scene(LightType light_type) {
    Scene scene;
    scene.name = "spheres";
    scene.camera.position = {0.0f, 3.0f, 8.0f};
    scene.camera.target = {0.0f, 0.5f, 0.0f};
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f)));
    int index = 0;
    for (int i = -2; i <= 2; ++i) {
        for (int j = -1; j <= 1; ++j) {
            const float radius = 0.5f + 0.1f * float((i + j + 4) % 3);
            scene.objects.push_back(
                sphere_object(fmt::format("sphere{}", index++), radius, {1.6f * float(i), radius, 1.6f * float(j)}, 48));
        }
    }
    scene.lights.push_back(light_type == LightType::rect ? downward_rect_light({0.5f, 5.0f, 0.5f}, {2.0f, 2.0f}, 40.0f)
                                                         : sphere_light({0.5f, 5.0f, 0.5f}, 0.5f, 40.0f));
    return scene;
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

// The rendered penumbra of a straight edge, through the whole renderer (camera rays, hit points,
// shadow-ray origins, the visibility and radiance images): the occluder is the half-plane x < 0
// at height 1, the light is centred above the edge at height 2, the ground is y = 0, and the
// camera looks straight down with its near plane clipping the occluder away. Returns, for every
// pixel of the middle row, the ground x at its centre and its visibility R and radiance.
struct EdgeProfile {
    std::vector<double> x, visible, radiance;
};

constexpr float kEdgeAlbedo = 0.5f;

EdgeProfile render_edge_profile(const Light& light) {
    Scene scene;
    scene.camera.position = {0.0f, 10.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};  // image x runs along world +x
    scene.camera.near_plane = 9.5f;         // the occluder, at distance 9, is not seen
    const int width = 120, height = 6;
    // 2.4 units of ground across the image: half-height 1.2 / 20 at distance 10.
    scene.camera.fov_y_degrees = float(2.0 * std::atan(1.2 / 20.0 / 10.0) * 180.0 / kPi);
    scene.ambient = glm::vec3(0.0f);
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f), glm::vec3(kEdgeAlbedo)));
    scene.objects.push_back(plane_object("occluder", {40.0f, 40.0f}, glm::vec3(-20.0f, 1.0f, 0.0f)));
    scene.lights.push_back(light);
    ReferenceSettings settings;
    settings.light_samples = 256;
    settings.pixel_samples = 4;
    const ReferenceImages images = render_reference(scene, build_scene_meshes(scene), width, height, settings);
    EdgeProfile profile;
    const int row = height / 2;
    for (int column = 0; column < width; ++column) {
        const Ray ray = primary_ray(scene.camera, width, height, float(column) + 0.5f, float(row) + 0.5f);
        REQUIRE(images.visibility.at(column, row)[1] == 1.0f);  // the ground, facing the light
        profile.x.push_back(ray.origin.x - ray.origin.y / ray.direction.y * ray.direction.x);
        profile.visible.push_back(images.visibility.at(column, row)[0]);
        profile.radiance.push_back(images.radiance.at(column, row)[0]);
    }
    REQUIRE(profile.x.front() < -1.1);
    REQUIRE(profile.x.back() > 1.1);
    return profile;
}

// Where a rising profile first reaches `level`, by linear interpolation between samples.
double crossing(const std::vector<double>& x, const std::vector<double>& values, double level) {
    for (size_t i = 1; i < x.size(); ++i)
        if (values[i - 1] < level && values[i] >= level)
            return x[i - 1] + (level - values[i - 1]) / (values[i] - values[i - 1]) * (x[i] - x[i - 1]);
    return std::nan("");
}

// Area of a spherical cap of angular radius `alpha` on one side of a great circle whose plane
// passes `delta` (radians, positive towards the centre) from the cap's centre (intersection of
// two caps, Tovchigrechko & Vakser 2001, with one of angular radius pi/2), over the cap's area.
double cap_fraction_beyond_plane(double alpha, double delta) {
    if (delta >= alpha) return 1.0;
    if (delta <= -alpha) return 0.0;
    const double gamma = kPi / 2.0 - delta;  // between the cap's centre and the half-space's pole
    const double area = 2.0 * (kPi - std::acos(std::cos(gamma) / std::sin(alpha)) -
                               std::cos(alpha) * std::acos(-std::cos(gamma) * std::cos(alpha) /
                                                           (std::sin(gamma) * std::sin(alpha))));
    return area / (2.0 * kPi * (1.0 - std::cos(alpha)));
}

}  // namespace

TEST_CASE("rect light frame: right = normalize(direction x up_hint), up = right x direction") {
    const Light light = downward_rect_light({1, 2, 3}, {2.0f, 1.0f}, 1.0f);
    const RectLightFrame frame = rect_light_frame(light);
    CHECK(frame.normal.y == doctest::Approx(-1.0));
    CHECK(frame.right.x == doctest::Approx(-1.0));
    CHECK(frame.up.z == doctest::Approx(1.0));
    CHECK(glm::dot(frame.right, frame.up) == doctest::Approx(0.0));
    CHECK(frame.point(1.0f, 0.5f).x == doctest::Approx(0.0));  // width runs along right
    CHECK(frame.point(1.0f, 0.5f).z == doctest::Approx(3.5));  // height along up
    CHECK(frame.area() == doctest::Approx(2.0));
}

TEST_CASE("stratified patterns: CMJ points are stratified in 2D and in both 1D projections") {
    const int count = 64;
    std::vector<int> columns(8, 0), rows(8, 0), cells(64, 0), fine_x(count, 0), fine_y(count, 0);
    for (int i = 0; i < count; ++i) {
        const glm::vec2 u = cmj_sample(uint32_t(i), count, 12345u);
        REQUIRE(u.x >= 0.0f);
        REQUIRE(u.x < 1.0f);
        REQUIRE(u.y >= 0.0f);
        REQUIRE(u.y < 1.0f);
        ++cells[int(u.y * 8) * 8 + int(u.x * 8)];
        ++fine_x[int(u.x * count)];
        ++fine_y[int(u.y * count)];
    }
    for (int c : cells) CHECK(c == 1);
    for (int c : fine_x) CHECK(c == 1);
    for (int c : fine_y) CHECK(c == 1);
}

TEST_CASE("rect light: irradiance on an unoccluded plane matches Lambert's polygon formula") {
    Scene scene;
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f)));
    scene.lights.push_back(downward_rect_light({0.3f, 1.5f, -0.2f}, {2.0f, 1.0f}, 5.0f));
    const auto meshes = build_scene_meshes(scene);
    const EmbreeScene embree(scene, meshes);
    const PreparedLight light = prepare_lights(scene, 256, 3)[0];
    const RectLightFrame frame = rect_light_frame(scene.lights[0]);
    std::vector<glm::dvec3> corners;
    for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
        corners.push_back(glm::dvec3(frame.point(corner.x * 1.0f, corner.y * 0.5f)));
    const double radiance = 5.0 / (2.0 * 1.0);

    struct Case {
        const char* what;
        glm::vec3 p, n;
    };
    const Case cases[] = {
        {"below the centre", {0.3f, 0.0f, -0.2f}, {0, 1, 0}},
        {"below a corner", glm::vec3(corners[2].x, 0.0, corners[2].z), {0, 1, 0}},
        {"outside the footprint", {3.0f, 0.0f, 1.0f}, {0, 1, 0}},
        {"tilted receiver", {0.0f, 0.0f, 0.0f}, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f))},
    };
    for (const Case& c : cases) {
        const PointEstimate e = estimate_at(embree, light, c.p, c.n, 32);
        check_estimate(e, polygon_irradiance(corners, glm::dvec3(c.p), glm::dvec3(c.n), radiance), c.what);
        CHECK(e.visible == doctest::Approx(1.0));
    }
}

TEST_CASE("sphere light: irradiance is I cos(theta) / d^2 while the sphere is above the horizon") {
    Scene scene;
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f)));
    scene.lights.push_back(sphere_light({0.0f, 2.0f, 0.0f}, 0.5f, 7.0f));
    const auto meshes = build_scene_meshes(scene);
    const EmbreeScene embree(scene, meshes);
    const PreparedLight light = prepare_lights(scene, 256, 5)[0];
    for (const float x : {0.0f, 1.0f, 1.8f}) {
        const glm::vec3 p(x, 0.0f, 0.0f);
        const glm::dvec3 to_light = glm::dvec3(0.0, 2.0, 0.0) - glm::dvec3(p);
        const double distance = glm::length(to_light);
        const double cos_theta = to_light.y / distance;
        REQUIRE(0.5 / distance < cos_theta);  // the whole sphere is above the horizon
        const PointEstimate e = estimate_at(embree, light, p, {0, 1, 0}, 32);
        check_estimate(e, 7.0 * cos_theta / (distance * distance), fmt::format("x = {}", x));
    }
}

TEST_CASE("straight occluder edge: the visible fraction of a rect light is linear across the penumbra") {
    // Light: width 1 along x (right = -x), at height 2. Occluder: the half-plane x < 0 at height 1.
    // A light point q is seen from receiver (x, 0, 0) iff the segment crosses height 1 at x >= 0,
    // i.e. q.x >= -x * (2 - 1) / 1, so the visible fraction is clamp(0.5 + x, 0, 1).
    Scene scene;
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f)));
    scene.objects.push_back(plane_object("occluder", {40.0f, 40.0f}, glm::vec3(-20.0f, 1.0f, 0.0f)));
    scene.lights.push_back(downward_rect_light({0.0f, 2.0f, 0.0f}, {1.0f, 0.5f}, 1.0f));
    const auto meshes = build_scene_meshes(scene);
    const EmbreeScene embree(scene, meshes);
    const PreparedLight light = prepare_lights(scene, 256, 9)[0];
    for (const float x : {-0.7f, -0.4f, -0.1f, 0.0f, 0.25f, 0.45f, 0.7f}) {
        const double exact = std::clamp(0.5 + double(x), 0.0, 1.0);
        const PointEstimate e = estimate_at(embree, light, {x, 0.0f, 0.1f}, {0, 1, 0}, 16);
        INFO("x = " << x << ": visible " << e.visible << " +- " << e.visible_sigma << ", exact " << exact);
        CHECK(std::abs(e.visible - exact) <= 4.0 * e.visible_sigma + 1e-6);
        CHECK(std::abs(e.visible - exact) <= 0.01);
    }
}

TEST_CASE("disk occluder on the axis of a sphere light: visible = 1 - (1 - cos a_disk) / (1 - cos a_light)") {
    const float light_height = 4.0f, light_radius = 1.0f, disk_height = 2.0f, disk_radius = 0.3f;
    Scene scene;
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f)));
    scene.objects.push_back(plane_object("disk", {1.0f, 1.0f}, {0.0f, disk_height, 0.0f}));
    scene.lights.push_back(sphere_light({0.0f, light_height, 0.0f}, light_radius, 3.0f));
    auto meshes = build_scene_meshes(scene);
    meshes[1] = disk_mesh(disk_radius, 2048);  // a true disk to within 2e-6 of its area
    const EmbreeScene embree(scene, meshes);
    const PreparedLight light = prepare_lights(scene, 1024, 11)[0];

    const double cos_light = std::sqrt(1.0 - double(light_radius * light_radius) / (light_height * light_height));
    const double cos_disk = disk_height / std::hypot(double(disk_height), double(disk_radius));
    REQUIRE(cos_disk > cos_light);  // the disk's cone lies inside the light's
    const double exact = 1.0 - (1.0 - cos_disk) / (1.0 - cos_light);
    const PointEstimate e = estimate_at(embree, light, glm::vec3(0.0f), {0, 1, 0}, 16);
    INFO("visible " << e.visible << " +- " << e.visible_sigma << ", exact " << exact);
    CHECK(std::abs(e.visible - exact) <= 4.0 * e.visible_sigma + 1e-6);
    CHECK(std::abs(e.visible - exact) <= 0.01);
    // Uniform radiance over a cone around the normal: irradiance is the visible share of pi L sin^2.
    const double unoccluded = 3.0 / (light_height * light_height);
    const double blocked = kPi * 3.0 / (kPi * light_radius * light_radius) * (1.0 - cos_disk * cos_disk);
    check_estimate(estimate_at(embree, light, glm::vec3(0.0f), {0, 1, 0}, 16), unoccluded - blocked,
                   "irradiance under the disk");
}

TEST_CASE("rendered penumbra of a straight edge under a rect light: linear, centred on the edge, as wide as the light") {
    // Light width w along x (right = -x): a light point q is seen from ground point x iff the
    // segment crosses height 1 at x >= 0, i.e. q.x >= -x, so V = clamp(1/2 + x / w, 0, 1): the
    // 50 % point on the geometric edge, 10 %-90 % over 0.8 w. The radiance is albedo / pi times
    // Lambert's irradiance of the visible part of the rectangle, x' in [max(-x, -w/2), w/2].
    for (const float light_width : {0.8f, 1.6f}) {
        CAPTURE(light_width);
        const float light_height = 0.5f, intensity = 4.0f;
        const Light light = downward_rect_light({0.0f, 2.0f, 0.0f}, {light_width, light_height}, intensity);
        const EdgeProfile profile = render_edge_profile(light);
        const double radiance = intensity / (light_width * light_height);
        int penumbra = 0;
        for (size_t i = 0; i < profile.x.size(); ++i) {
            const double x = profile.x[i];
            const double expected = std::clamp(0.5 + x / light_width, 0.0, 1.0);
            INFO("x = " << x << ": visible " << profile.visible[i] << ", exact " << expected);
            CHECK(std::abs(profile.visible[i] - expected) <= 0.01);
            penumbra += expected > 0.0 && expected < 1.0;
            // Visible part of the light: world x from max(-x, -w/2) to w/2, z within +-h/2.
            const double x0 = std::max(-x, -0.5 * light_width), x1 = 0.5 * light_width;
            double exact = 0.0;
            if (x1 > x0) {
                const std::vector<glm::dvec3> corners = {{x0, 2.0, -0.5 * light_height}, {x1, 2.0, -0.5 * light_height},
                                                         {x1, 2.0, 0.5 * light_height}, {x0, 2.0, 0.5 * light_height}};
                exact = kEdgeAlbedo / kPi * polygon_irradiance(corners, {x, 0.0, 0.0}, {0.0, 1.0, 0.0}, radiance);
            }
            const double lit = kEdgeAlbedo / kPi * intensity / 4.0;  // the whole light overhead, roughly
            CHECK(std::abs(profile.radiance[i] - exact) <= 0.01 * lit);
        }
        CHECK(penumbra > 30);
        // Where and how wide, said directly.
        CHECK(std::abs(crossing(profile.x, profile.visible, 0.5)) <= 0.01);
        const double width = crossing(profile.x, profile.visible, 0.9) - crossing(profile.x, profile.visible, 0.1);
        CHECK(width == doctest::Approx(0.8 * light_width).epsilon(0.03));
    }
}

TEST_CASE("rendered penumbra of a straight edge under a sphere light: the spherical cap cut by the edge's plane") {
    // From ground point x the edge's plane (through the point and the line x = 0 at height 1)
    // passes sin(delta) = x / (sqrt(1 + x^2) sqrt(4 + x^2)) from the direction to the centre
    // (0, 2, 0); the visible fraction is the share of the light's cap, angular radius
    // asin(r / d), beyond that plane: a penumbra over |x| < r / sqrt(1 - r^2).
    for (const float radius : {0.15f, 0.3f}) {
        CAPTURE(radius);
        const EdgeProfile profile = render_edge_profile(sphere_light({0.0f, 2.0f, 0.0f}, radius, 4.0f));
        int penumbra = 0;
        std::vector<double> exact;
        for (size_t i = 0; i < profile.x.size(); ++i) {
            const double x = profile.x[i];
            const double distance = std::hypot(x, 2.0);
            const double alpha = std::asin(radius / distance);
            const double delta = std::asin(x / (std::sqrt(1.0 + x * x) * distance));
            const double expected = cap_fraction_beyond_plane(alpha, delta);
            INFO("x = " << x << ": visible " << profile.visible[i] << ", exact " << expected);
            CHECK(std::abs(profile.visible[i] - expected) <= 0.01);
            penumbra += expected > 0.0 && expected < 1.0;
            exact.push_back(expected);
        }
        CHECK(penumbra > 10);
        CHECK(std::abs(crossing(profile.x, profile.visible, 0.5)) <= 0.01);
        const auto width = [&](const std::vector<double>& values) {
            return crossing(profile.x, values, 0.9) - crossing(profile.x, values, 0.1);
        };
        CHECK(width(profile.visible) == doctest::Approx(width(exact)).epsilon(0.05));
        // A small cap is nearly a disk of radius r (in x): 10 %-90 % of a disk's segment area over 1.374 r.
        CHECK(width(exact) == doctest::Approx(1.374 * radius).epsilon(0.05));
    }
}

TEST_CASE("camera: a sphere on the primary ray of a pixel shows up at that pixel") {
    Scene scene = camera_scene();
    const int width = 32, height = 24, target_x = 5, target_y = 3;
    const Ray ray = primary_ray(scene.camera, width, height, target_x + 0.5f, target_y + 0.5f);
    const float distance = 5.0f;
    const float pixel_size = distance * 2.0f * std::tan(glm::radians(scene.camera.fov_y_degrees) * 0.5f) / height;
    scene.objects.push_back(sphere_object("marker", 0.6f * pixel_size, ray.origin + distance * ray.direction));
    scene.objects[0].material.albedo = glm::vec3(1.0f);
    scene.ambient = glm::vec3(1.0f);
    ReferenceSettings settings;
    settings.light_samples = 4;
    settings.pixel_samples = 16;
    const ReferenceImages images = render_reference(scene, build_scene_meshes(scene), width, height, settings);
    int brightest_x = -1, brightest_y = -1;
    float brightest = -1.0f;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float value = images.radiance.at(x, y)[0];
            if (value > brightest) brightest = value, brightest_x = x, brightest_y = y;
            if (std::abs(x - target_x) >= 2 || std::abs(y - target_y) >= 2) CHECK(value == 0.0f);
        }
    }
    CHECK(brightest_x == target_x);
    CHECK(brightest_y == target_y);
    CHECK(brightest > 0.5f);
}

TEST_CASE("background: rays that hit nothing get the background, visibility G = 0 and no variance") {
    Scene scene = camera_scene();
    scene.background = {0.2f, 0.3f, 0.4f};
    scene.lights.push_back(downward_rect_light({0.0f, 5.0f, 0.0f}, {1.0f, 1.0f}, 10.0f));
    // A floor seen in the lower half of the image; the upper half is sky.
    scene.objects.push_back(plane_object("floor", {100.0f, 100.0f}, {0.0f, -1.0f, 0.0f}));
    ReferenceSettings settings;
    settings.light_samples = 16;
    const ReferenceImages images = render_reference(scene, build_scene_meshes(scene), 16, 12, settings);
    for (int x = 0; x < 16; ++x) {
        const float* sky = images.radiance.at(x, 0);
        CHECK(sky[0] == 0.2f);
        CHECK(sky[1] == 0.3f);
        CHECK(sky[2] == 0.4f);
        CHECK(sky[3] == 1.0f);
        CHECK(images.visibility.at(x, 0)[1] == 0.0f);
        CHECK(images.visibility.at(x, 0)[0] == 0.0f);
        CHECK(images.variance.at(x, 0)[0] == 0.0f);
        CHECK(images.visibility.at(x, 11)[1] == 1.0f);  // the floor faces the light
        CHECK(images.visibility.at(x, 11)[0] == 1.0f);  // nothing occludes it
        CHECK(images.visibility.at(x, 11)[3] == 1.0f);
    }
    CHECK(images.shadow_rays > 0);
}

TEST_CASE("point-like lights: shading equals shading.h with hard, exact visibility") {
    using namespace canopy::shader;
    Scene scene;
    scene.camera.position = {0.0f, 10.0f, 0.001f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fov_y_degrees = 30.0f;
    scene.ambient = {0.05f, 0.04f, 0.03f};
    const glm::vec3 albedo(0.7f, 0.5f, 0.3f);
    scene.objects.push_back(plane_object("ground", {40.0f, 40.0f}, glm::vec3(0.0f), albedo));
    // A blocker covering x > 0 at height 1: casts a hard shadow from the directional light.
    scene.objects.push_back(plane_object("blocker", {20.0f, 40.0f}, {10.0f, 1.0f, 0.0f}));
    scene.objects[1].material.albedo = glm::vec3(0.0f);
    Light sun;
    sun.type = LightType::directional;
    sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    sun.color = {1.0f, 0.9f, 0.8f};
    sun.intensity = 2.0f;
    Light spot;
    spot.type = LightType::spot;
    // Above the blocker, but it casts no shadows, so it is never occluded. Far and wide enough that
    // its irradiance hardly changes across a pixel (camera samples are jittered inside pixels).
    spot.position = {-1.0f, 6.0f, 0.0f};
    spot.direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.0f));
    spot.spot_angle_degrees = 75.0f;
    spot.intensity = 8.0f;
    spot.casts_shadows = false;
    scene.lights = {sun, spot};
    // Hide the blocker from the camera so that the ground below it is seen.
    scene.objects[1].instances[0].translate.y = 1.0f;
    scene.camera.near_plane = 9.5f;  // clips the blocker (at distance 9) away, as the rasteriser would
    const int size = 48;
    ReferenceSettings settings;
    settings.pixel_samples = 1;
    const ReferenceImages images = render_reference(scene, build_scene_meshes(scene), size, size, settings);

    int lit = 0, shadowed = 0;
    for (int y = 2; y < size - 2; ++y) {
        for (int x = 2; x < size - 2; ++x) {
            // The camera sample is jittered inside the pixel: compare at the pixel centre, away from the
            // shadow edge.
            const Ray ray = primary_ray(scene.camera, size, size, x + 0.5f, y + 0.5f);
            const float t = -ray.origin.y / ray.direction.y;
            const glm::vec3 p = ray.origin + t * ray.direction;
            const glm::vec3 n(0, 1, 0);
            const glm::vec3 spot_irradiance = point_irradiance(LIGHT_SPOT, p, n, spot.position, spot.direction,
                                                               spot.color * spot.intensity,
                                                               std::cos(glm::radians(spot.spot_angle_degrees)));
            const glm::vec3 sun_irradiance = directional_irradiance(n, sun.direction, sun.color * sun.intensity);
            // The sun's shadow edge on the ground: rays towards -direction cross height 1 at x >= 0.
            const float crossing_x = p.x + (1.0f / -sun.direction.y) * -sun.direction.x;
            const float pixel_size = 10.0f * std::tan(glm::radians(15.0f)) * 2.0f / size;
            if (std::abs(crossing_x) < 0.8f * pixel_size) continue;  // jitter reaches 0.71 pixels
            const bool in_shadow = crossing_x > 0.0f && p.x > -20.0f;
            const glm::vec3 expected =
                lambert_radiance(albedo, sun_irradiance * (in_shadow ? 0.0f : 1.0f) + spot_irradiance, 1.0f, scene.ambient);
            const float* pixel = images.radiance.at(x, y);
            INFO("pixel " << x << "," << y << std::string(in_shadow ? " shadowed" : " lit"));
            CHECK(pixel[0] == doctest::Approx(expected.r).epsilon(0.02));
            CHECK(pixel[1] == doctest::Approx(expected.g).epsilon(0.02));
            CHECK(pixel[2] == doctest::Approx(expected.b).epsilon(0.02));
            CHECK(images.visibility.at(x, y)[0] == (in_shadow ? 0.0f : 1.0f));
            (in_shadow ? shadowed : lit) += 1;
        }
    }
    CHECK(lit > 50);
    CHECK(shadowed > 50);
}

TEST_CASE("render: a pixel under a rect light equals albedo * (E / pi + ambient), within its variance") {
    Scene scene;
    scene.camera.position = {0.0f, 3.0f, 0.0001f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fov_y_degrees = 0.5f;  // a tiny footprint: the irradiance is constant across the pixel
    scene.ambient = {0.02f, 0.02f, 0.02f};
    const glm::vec3 albedo(0.6f, 0.6f, 0.6f);
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f), albedo));
    scene.lights.push_back(downward_rect_light({0.4f, 1.0f, 0.2f}, {1.0f, 0.6f}, 2.0f));
    ReferenceSettings settings;
    settings.light_samples = 64;
    settings.pixel_samples = 4;
    const int size = 8;
    const ReferenceImages images = render_reference(scene, build_scene_meshes(scene), size, size, settings);

    const RectLightFrame frame = rect_light_frame(scene.lights[0]);
    std::vector<glm::dvec3> corners;
    for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
        corners.push_back(glm::dvec3(frame.point(corner.x * 0.5f, corner.y * 0.3f)));
    const double exact_irradiance = polygon_irradiance(corners, glm::dvec3(0.0), glm::dvec3(0, 1, 0), 2.0 / 0.6);
    const double exact = 0.6 * (exact_irradiance / kPi + 0.02);
    // The mean over the whole (nearly uniform) image, and its standard error from the variance image.
    double sum = 0, variance = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) sum += images.radiance.at(x, y)[0], variance += images.variance.at(x, y)[0];
    const double mean = sum / (size * size), sigma = std::sqrt(variance) / (size * size);
    INFO("mean " << mean << " +- " << sigma << ", exact " << exact);
    CHECK(std::abs(mean - exact) <= 4.0 * sigma + 1e-4 * exact);
    CHECK(std::abs(mean - exact) <= 0.01 * exact);
    CHECK(images.radiance.at(3, 3)[3] == 1.0f);
}

TEST_CASE("variance image: not smaller than the actual spread between independent renders") {
    Scene scene = spheres_scene(LightType::rect);
    const auto meshes = build_scene_meshes(scene);
    ReferenceSettings a;
    a.light_samples = 16;
    a.pixel_samples = 2;
    ReferenceSettings b = a;
    b.seed = 2;
    const int width = 48, height = 27;
    const ReferenceImages first = render_reference(scene, meshes, width, height, a);
    const ReferenceImages second = render_reference(scene, meshes, width, height, b);
    double squared_difference = 0, predicted = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const double d = first.radiance.at(x, y)[1] - second.radiance.at(x, y)[1];
            squared_difference += d * d;
            predicted += first.variance.at(x, y)[1] + second.variance.at(x, y)[1];
        }
    }
    INFO("measured " << squared_difference << ", predicted " << predicted);
    CHECK(predicted > 0.0);
    CHECK(squared_difference <= 1.2 * predicted);
    CHECK(squared_difference >= 0.05 * predicted);  // conservative, but not absurdly so
}

TEST_CASE("render: deterministic for a seed, independent of the thread count; progress reaches 1") {
    Scene scene = spheres_scene(LightType::sphere);
    const auto meshes = build_scene_meshes(scene);
    ReferenceSettings settings;
    settings.light_samples = 8;
    settings.pixel_samples = 2;
    settings.threads = 1;
    std::vector<double> progress;
    const ReferenceImages one =
        render_reference(scene, meshes, 40, 24, settings, [&](double done) { progress.push_back(done); });
    settings.threads = 2;
    const ReferenceImages two = render_reference(scene, meshes, 40, 24, settings);
    CHECK(same_pixels(one.radiance, two.radiance));
    CHECK(same_pixels(one.variance, two.variance));
    CHECK(same_pixels(one.visibility, two.visibility));
    CHECK(one.shadow_rays == two.shadow_rays);
    REQUIRE(!progress.empty());
    CHECK(progress.back() == 1.0);
    CHECK(std::is_sorted(progress.begin(), progress.end()));
    settings.seed = 5;
    CHECK_FALSE(same_pixels(render_reference(scene, meshes, 40, 24, settings).radiance, one.radiance));
}

TEST_CASE("objects and lights that do not cast shadows are not occluders / not occluded") {
    Scene scene;
    scene.camera.position = {0.0f, 10.0f, 0.001f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fov_y_degrees = 10.0f;
    scene.camera.near_plane = 9.5f;  // the blocker at height 1 is clipped away from the camera
    scene.objects.push_back(plane_object("ground", {20.0f, 20.0f}, glm::vec3(0.0f)));
    scene.objects.push_back(plane_object("blocker", {20.0f, 20.0f}, {0.0f, 1.0f, 0.0f}));
    Light sun;
    sun.type = LightType::directional;
    scene.lights = {sun};
    ReferenceSettings settings;
    settings.pixel_samples = 1;
    const auto meshes = build_scene_meshes(scene);
    CHECK(render_reference(scene, meshes, 4, 4, settings).visibility.at(2, 2)[0] == 0.0f);
    scene.objects[1].casts_shadows = false;
    CHECK(render_reference(scene, meshes, 4, 4, settings).visibility.at(2, 2)[0] == 1.0f);
    scene.objects[1].casts_shadows = true;
    scene.lights[0].casts_shadows = false;  // no shadow light left: G = 0, but the light still shines
    const ReferenceImages images = render_reference(scene, meshes, 4, 4, settings);
    CHECK(images.visibility.at(2, 2)[1] == 0.0f);
    CHECK(images.radiance.at(2, 2)[0] == doctest::Approx(0.5f * (3.0f / shader::PI + 0.03f)));
    CHECK(images.shadow_rays == 0);
}

TEST_CASE("alpha-test hook: a filter that discards every other triangle lets rays through those") {
    // A 16 x 16 grid of quads at height 1; odd triangles are transparent.
    Scene scene;
    scene.objects.push_back(plane_object("grid", {1.0f, 1.0f}, {0.0f, 1.0f, 0.0f}));
    TriangleMesh grid;
    const int cells = 16;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i)
            grid.vertices.push_back({glm::vec3(float(i) / cells - 0.5f, 0.0f, float(j) / cells - 0.5f), glm::vec3(0, 1, 0)});
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            const uint32_t a = uint32_t(j * (cells + 1) + i), b = a + 1, c = a + cells + 1, d = c + 1;
            grid.indices.insert(grid.indices.end(), {a, c, b, b, c, d});
        }
    }
    std::atomic<int> calls{0};
    EmbreeSceneOptions options;
    options.alpha_tests = {[&](uint32_t triangle, float, float) {
        ++calls;
        return triangle % 2 == 0;
    }};
    const EmbreeScene embree(scene, {grid}, options);

    RTCIntersectContext context{};
    rtcInitIntersectContext(&context);
    int blocked = 0, passed = 0, hits_on_odd = 0;
    for (size_t t = 0; t < grid.triangle_count(); ++t) {
        glm::vec3 centroid(0.0f);
        for (int k = 0; k < 3; ++k) centroid += grid.vertices[grid.indices[t * 3 + k]].position / 3.0f;
        centroid.y += 1.0f;
        RTCRayHit hit{};
        hit.ray = {centroid.x, 0.0f, centroid.z, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 10.0f, 0xffffffffu, 0, 0};
        hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        RTCRay shadow = hit.ray;
        rtcOccluded1(embree.shadow_scene(), &context, &shadow);
        const bool occluded = shadow.tfar < 0.0f;
        CHECK(occluded == (t % 2 == 0));
        (occluded ? blocked : passed) += 1;
        rtcIntersect1(embree.visible_scene(), &context, &hit);
        const bool hit_something = hit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        CHECK(hit_something == (t % 2 == 0));
        if (hit_something && hit.hit.primID % 2 == 1) ++hits_on_odd;
    }
    CHECK(blocked == int(grid.triangle_count() / 2));
    CHECK(passed == int(grid.triangle_count() / 2));
    CHECK(hits_on_odd == 0);
    CHECK(calls.load() > 0);

    // Through the renderer's packets: half of a light straight above shines through.
    Scene lit;
    lit.lights.push_back(downward_rect_light({0.0f, 1.2f, 0.0f}, {0.1f, 0.1f}, 1.0f));
    const PreparedLight light = prepare_lights(lit, 256, 1)[0];
    const PointEstimate e = estimate_at(embree, light, {0.01f, 0.0f, 0.013f}, {0, 1, 0}, 8);
    CHECK(e.visible > 0.2);
    CHECK(e.visible < 0.8);
}

TEST_CASE("unrepresentable scene content is a ConfigError naming its file:line") {
    Scene scene = camera_scene();
    scene.objects.push_back(plane_object("floor", {4.0f, 4.0f}, {0.0f, -1.0f, 0.0f}));
    const auto meshes = build_scene_meshes(scene);
    ReferenceSettings settings;
    settings.light_samples = 4;
    settings.pixel_samples = 1;
    const auto expect_error = [&](const Scene& bad, const std::string& file, int line, const std::string& words) {
        try {
            render_reference(bad, meshes, 4, 4, settings);
            FAIL("expected a ConfigError about " << words);
        } catch (const ConfigError& error) {
            CHECK(error.file() == file);
            CHECK(error.line() == line);
            INFO(error.what());
            CHECK(std::string(error.what()).find(words) != std::string::npos);
        }
    };
    Scene unknown = scene;
    unknown.lights.push_back(downward_rect_light({0, 2, 0}, {1, 1}, 1));
    unknown.lights[0].type = LightType(42);
    unknown.lights[0].where = {"scenes/odd.toml", 17};
    expect_error(unknown, "scenes/odd.toml", 17, "light type");

    Scene parallel = scene;
    parallel.lights.push_back(downward_rect_light({0, 2, 0}, {1, 1}, 1));
    parallel.lights[0].rect_up_hint = {0.0f, 2.0f, 0.0f};
    expect_error(parallel, "test.toml", 30, "parallel");

    Scene point_sphere = scene;
    point_sphere.lights.push_back(sphere_light({0, 2, 0}, 0.0f, 1.0f));
    expect_error(point_sphere, "test.toml", 40, "radius");

    Scene flat = scene;
    flat.objects[0].instances[0].scale = {1.0f, 0.0f, 1.0f};
    expect_error(flat, "test.toml", 10, "degenerate");

    Scene blind = scene;
    blind.file = "scenes/blind.toml";
    blind.camera.up = glm::vec3(0.0f, 0.0f, 2.0f);  // parallel to the view direction -z
    expect_error(blind, "scenes/blind.toml", 0, "parallel");
}

TEST_CASE("cache key: changes with every input that changes the image, and only with those") {
    const Scene base = spheres_scene(LightType::rect);
    const auto base_meshes = build_scene_meshes(base);
    ReferenceSettings settings;
    const std::string key = reference_cache_key(base, base_meshes, 64, 36, settings);
    CHECK(key.size() == 16);
    CHECK(reference_cache_key(base, base_meshes, 64, 36, settings) == key);

    const auto changed = [&](const std::function<void(Scene&, std::vector<TriangleMesh>&, int&, int&,
                                                      ReferenceSettings&)>& change) {
        Scene scene = base;
        auto meshes = base_meshes;
        int width = 64, height = 36;
        ReferenceSettings s = settings;
        change(scene, meshes, width, height, s);
        return reference_cache_key(scene, meshes, width, height, s) != key;
    };
    using M = std::vector<TriangleMesh>;
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.camera.position.x += 0.01f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.camera.target.y += 0.01f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.camera.up = {0.1f, 1.0f, 0.0f}; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.camera.fov_y_degrees = 50.0f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.camera.near_plane = 0.1f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.camera.far_plane = 50.0f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.ambient.g = 0.5f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.background.b = 0.5f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights[0].intensity = 41.0f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights[0].position.z = 0.6f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights[0].rect_size.y = 1.5f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights[0].rect_up_hint = {1, 0, 0}; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights[0].color.r = 0.9f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights[0].casts_shadows = false; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights.push_back(s.lights[0]); }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.objects[2].material.albedo.r = 0.1f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.objects[2].casts_shadows = false; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.objects[3].instances[0].translate.x += 0.001f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.objects[3].instances[0].rotate_degrees.y = 5.0f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.objects[3].instances[0].outer[3][0] = 1.0f; }));
    CHECK(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.objects[3].instances.push_back(Transform{}); }));
    CHECK(changed([](Scene&, M& m, int&, int&, ReferenceSettings&) { m[1].vertices[7].position.y += 1e-4f; }));
    CHECK(changed([](Scene&, M& m, int&, int&, ReferenceSettings&) { m[1].vertices[7].normal.x += 1e-4f; }));
    CHECK(changed([](Scene&, M& m, int&, int&, ReferenceSettings&) { std::swap(m[1].indices[0], m[1].indices[1]); }));
    CHECK(changed([](Scene&, M&, int& w, int&, ReferenceSettings&) { w = 65; }));
    CHECK(changed([](Scene&, M&, int&, int& h, ReferenceSettings&) { h = 35; }));
    CHECK(changed([](Scene&, M&, int&, int&, ReferenceSettings& r) { r.light_samples = 128; }));
    CHECK(changed([](Scene&, M&, int&, int&, ReferenceSettings& r) { r.pixel_samples = 9; }));
    CHECK(changed([](Scene&, M&, int&, int&, ReferenceSettings& r) { r.seed = 2; }));
    // Neither names, source locations nor the thread count change the image.
    CHECK_FALSE(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.name = "renamed"; }));
    CHECK_FALSE(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.objects[0].name = "floor"; }));
    CHECK_FALSE(changed([](Scene& s, M&, int&, int&, ReferenceSettings&) { s.lights[0].where.line = 99; }));
    CHECK_FALSE(changed([](Scene&, M&, int&, int&, ReferenceSettings& r) { r.threads = 7; }));
}

TEST_CASE("cache files: store then load round-trips every pixel and the statistics") {
    Scene scene = spheres_scene(LightType::sphere);
    const auto meshes = build_scene_meshes(scene);
    ReferenceSettings settings;
    settings.light_samples = 4;
    settings.pixel_samples = 1;
    const ReferenceImages images = render_reference(scene, meshes, 20, 12, settings);
    const std::string key = reference_cache_key(scene, meshes, 20, 12, settings);
    const test::TempFolder folder("canopy-test-reference");
    const std::filesystem::path dir = folder.path() / "cache";
    CHECK_FALSE(load_cached_reference(dir, key).has_value());
    store_reference(dir, key, images);
    for (const char* name : {"radiance", "variance", "visibility"})
        CHECK(std::filesystem::is_regular_file(dir / fmt::format("{}.{}.exr", key, name)));
    CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 3);

    const std::optional<ReferenceImages> loaded = load_cached_reference(dir, key);
    REQUIRE(loaded.has_value());
    CHECK(same_pixels(loaded->radiance, images.radiance));
    CHECK(same_pixels(loaded->variance, images.variance));
    CHECK(same_pixels(loaded->visibility, images.visibility));
    CHECK(loaded->seconds == images.seconds);
    CHECK(loaded->shadow_rays == images.shadow_rays);

    CHECK_FALSE(load_cached_reference(dir, "0123456789abcdef").has_value());
    // A file renamed to another key is not trusted.
    std::filesystem::copy_file(dir / fmt::format("{}.radiance.exr", key), dir / "0123456789abcdef.radiance.exr");
    std::filesystem::copy_file(dir / fmt::format("{}.variance.exr", key), dir / "0123456789abcdef.variance.exr");
    std::filesystem::copy_file(dir / fmt::format("{}.visibility.exr", key), dir / "0123456789abcdef.visibility.exr");
    CHECK_FALSE(load_cached_reference(dir, "0123456789abcdef").has_value());
    // A missing image is a miss.
    std::filesystem::remove(dir / fmt::format("{}.variance.exr", key));
    CHECK_FALSE(load_cached_reference(dir, key).has_value());
}

TEST_CASE("shadow-ray benchmark: measures both rates on the same rays") {
    Scene scene = spheres_scene(LightType::rect);
    ReferenceSettings settings;
    settings.light_samples = 16;
    settings.pixel_samples = 1;
    const ShadowRayBenchmark result = benchmark_shadow_rays(scene, build_scene_meshes(scene), 64, 36, settings);
    CHECK(result.rays > 0);
    CHECK(result.reference_rays_per_second > 0.0);
    CHECK(result.bare_rays_per_second > 0.0);
    CHECK(result.ratio == doctest::Approx(result.reference_rays_per_second / result.bare_rays_per_second));
}

// The performance targets, run on demand (`test_reference --no-skip -tc="*performance*"`): a
// 640x360 spheres reference with 256 area-light samples per pixel sample, and the shadow-ray
// throughput of the renderer against a bare rtcOccluded1 loop.
TEST_CASE("performance: 640x360 spheres reference and shadow-ray throughput" * doctest::skip()) {
    Scene scene = spheres_scene(LightType::rect);
    const auto meshes = build_scene_meshes(scene);
    ReferenceSettings settings;
    settings.light_samples = 256;
    settings.pixel_samples = 4;
    const ReferenceImages images = render_reference(scene, meshes, 640, 360, settings);
    MESSAGE(fmt::format("640x360, {} light x {} pixel samples: {:.2f} s, {} shadow rays ({:.1f} M/s)",
                        settings.light_samples, settings.pixel_samples, images.seconds, images.shadow_rays,
                        double(images.shadow_rays) / images.seconds * 1e-6));
    CHECK(images.seconds < 10.0);
    settings.light_samples = 64;
    const ShadowRayBenchmark bench = benchmark_shadow_rays(scene, meshes, 640, 360, settings);
    MESSAGE(fmt::format("reference {:.1f} M rays/s, bare rtcOccluded1 {:.1f} M rays/s, ratio {:.2f}",
                        bench.reference_rays_per_second * 1e-6, bench.bare_rays_per_second * 1e-6, bench.ratio));
    CHECK(bench.ratio >= 0.8);
}

TEST_CASE("reference: a directional light's shadow rays are finite segments reaching past the scene's bounds") {
    Scene scene;
    Light sun;
    sun.type = LightType::directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    scene.lights.push_back(sun);
    std::vector<PreparedLight> lights = prepare_lights(scene, 16, 1);
    REQUIRE(lights.size() == 1);
    CHECK(std::isinf(lights[0].shadow_reach));
    limit_shadow_reach(lights, 7.5f);
    CHECK(std::isfinite(lights[0].shadow_reach));
    CHECK(lights[0].shadow_reach >= 15.0f);  // any two points of the scene lie within it
    CHECK(lights[0].shadow_reach <= 15.1f);
}
