// Integration on the Vulkan device (lavapipe by default): every shadow technique, in several
// settings and under every light type, darkens the floor under an occluder, lights the open
// floor exactly as the shading model says, and renders identically twice.
#include "render/frame_renderer.hpp"
#include "scene/camera.hpp"
#include "shading.h"
#include "support/technique_variants.hpp"
#include "support/test_gpu.hpp"
#include "support/tiny_scene.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

using namespace canopy;

namespace {

constexpr int kWidth = 96, kHeight = 64;

Image render(const Scene& scene, const std::string& technique, const std::map<std::string, ParamValue>& given = {}) {
    return test::render_technique(scene, technique, given, kWidth, kHeight);
}

// Mean luminance of a 3x3 block around the pixel that shows world point p.
float luminance_at(const Image& image, const Scene& scene, glm::vec3 p) {
    const glm::vec2 px = project_to_pixel(scene.camera, image.width, image.height, p);
    float sum = 0.0f;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) sum += image.luminance(int(px.x) + dx, int(px.y) + dy);
    return sum / 9.0f;
}

void check_all_finite(const Image& image) {
    long long bad = 0;
    for (float v : image.pixels) bad += std::isfinite(v) ? 0 : 1;
    CHECK_MESSAGE(bad == 0, "non-finite channel values: ", bad);
}

}  // namespace

TEST_CASE("under the occluder is dark and the open floor is lit exactly as Lambert says") {
    const Scene scene = test::tiny_scene_under_rect_light();
    const Light& light = scene.lights.front();
    const glm::vec3 under_occluder(0.0f, 0.0f, 0.0f), open_floor(-1.8f, 0.0f, 1.5f);
    // Raster techniques light with the rect light's centre: the shading model's point_irradiance.
    const float albedo = 0.8f, ambient = 0.05f;
    const float irradiance = shader::point_irradiance(shader::LIGHT_RECT, open_floor, glm::vec3(0, 1, 0), light.position,
                                                      light.direction, glm::vec3(light.intensity), 1.0f).x;
    const float lit_expected = albedo * (irradiance / shader::PI + ambient);
    const float umbra_expected = albedo * ambient;
    for (const test::TechniqueVariant& v : test::technique_variants("shadow")) {
        const std::string name = test::describe(v);
        CAPTURE(name);
        const Image image = render(scene, v.technique, v.params);
        check_all_finite(image);
        const float lit = luminance_at(image, scene, open_floor);
        const float shadowed = luminance_at(image, scene, under_occluder);
        CHECK(lit == doctest::Approx(lit_expected).epsilon(0.01));
        CHECK(shadowed == doctest::Approx(umbra_expected).epsilon(0.05));
        CHECK(shadowed < 0.3f * lit);
    }
}

TEST_CASE("every light type casts the occluder's shadow") {
    for (LightType type : {LightType::spot, LightType::rect, LightType::sphere}) {
        Scene scene = test::tiny_scene();
        Light& light = scene.lights.front();
        light.type = type;
        light.position = glm::vec3(0.0f, 4.0f, 0.0f);
        light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
        light.intensity = 30.0f;
        light.spot_angle_degrees = 50.0f;
        light.rect_size = glm::vec2(0.2f);
        light.sphere_radius = 0.1f;
        CAPTURE(int(type));
        for (const char* technique : {"shadow.hard", "shadow.pcf", "shadow.vsm", "shadow.msm"}) {
            CAPTURE(technique);
            const Image image = render(scene, technique);
            check_all_finite(image);
            // Raster techniques light with the area light's centre: the shading model's point_irradiance.
            const glm::vec3 open_floor(-1.6f, 0.0f, 1.4f);
            const glm::vec3 E = shader::point_irradiance(int(type), open_floor, glm::vec3(0, 1, 0), light.position,
                                                         light.direction, glm::vec3(light.intensity),
                                                         std::cos(glm::radians(light.spot_angle_degrees)));
            const float lit_expected = 0.8f * (E.x / shader::PI + 0.05f);
            const float lit = luminance_at(image, scene, open_floor);
            const float shadowed = luminance_at(image, scene, glm::vec3(0.0f));
            CHECK(lit == doctest::Approx(lit_expected).epsilon(0.02));
            CHECK(shadowed < 0.3f * lit);
        }
    }
}

TEST_CASE("the same configuration renders identical images: any renderer, any order, any frame") {
    // Every registered technique and variant, each image from a FrameRenderer of its own. The
    // second round goes in reverse order, so memory a technique might read before writing it
    // held another technique's data rather than its own last image; and it renders two frames,
    // as runs keep the last of several (a technique must carry no state from frame to frame).
    const Scene scene = test::tiny_scene_under_rect_light();
    const std::vector<test::TechniqueVariant> all = test::technique_variants("shadow");
    std::vector<Image> first;
    for (const test::TechniqueVariant& v : all) first.push_back(render(scene, v.technique, v.params));
    const auto same_bits = [](const Image& a, const Image& b) {
        return a.pixels.size() == b.pixels.size() &&
               std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
    };
    for (size_t i = all.size(); i-- > 0;) {
        const test::TechniqueVariant& v = all[i];
        const std::string name = test::describe(v);
        CAPTURE(name);
        FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight,
                               test::technique_graph(v.technique, v.params));
        renderer.render();
        const Image frame1 = renderer.read_color();
        renderer.render();
        const Image frame2 = renderer.read_color();
        CHECK(same_bits(frame1, first[i]));
        CHECK(same_bits(frame2, first[i]));
        // Not two equally empty images: the occluder's shadow and the lit floor are both there.
        const float shadowed = luminance_at(frame1, scene, glm::vec3(0.0f));
        const float lit = luminance_at(frame1, scene, glm::vec3(-1.8f, 0.0f, 1.5f));
        CHECK(shadowed < 0.3f * lit);
    }
}

TEST_CASE("memory is reported per technique: the shadow map is the technique's") {
    const Scene scene = test::tiny_scene();
    for (long long resolution : {256LL, 1024LL}) {
        FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight,
                               test::technique_graph("shadow.hard", {{"resolution", resolution}}));
        const MemoryUse m = renderer.memory();
        CHECK(m.technique_bytes >= uint64_t(resolution * resolution * 4));   // D32F texels
        CHECK(m.technique_bytes < uint64_t(resolution * resolution * 4 * 2));
        CHECK(m.target_bytes >= uint64_t(kWidth * kHeight * (16 + 4)));
        CHECK(m.scene_bytes > 0);
        CHECK(renderer.pass_names() == std::vector<std::string>{"shadow_map", "lit"});
        const FrameTiming t = renderer.render();
        CHECK(t.pass_gpu_ms.size() == 2);
        CHECK(t.gpu_ms > 0.0);
        CHECK(t.wall_ms > 0.0);
    }
}

TEST_CASE("a scene without a shadow-casting light is refused with a reason") {
    Scene scene = test::tiny_scene();
    scene.lights.front().casts_shadows = false;
    const auto reason = unsupported_reason(test::gpu(), scene, test::technique_graph("shadow.hard"));
    REQUIRE(reason.has_value());
    CHECK(reason->find("shadow-casting") != std::string::npos);
}
