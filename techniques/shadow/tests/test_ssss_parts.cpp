// shadow.ssss, part by part (Gumbau 2011 ch. 6), on the device where the part is a shader:
//  * the coarse map: each texel the minimum of its block of the shadow map (6.2.1);
//  * its dilation, whose reach follows the light's size (L1614) -- in a synthetic map and in a
//    rendered scene as the light grows;
//  * the Gaussian's sigma from eq 6.2, in numbers and as the screen pass writes it;
//  * the blur's taps (Gaussian weights of the pixels actually read), its depth-discontinuity
//    rejection (6.2.3), lazy shadowing (6.3.2) and the mask of pixels it leaves alone (6.2.2).
// Synthetic inputs run through the technique's own passes (its ShadowPlan's FilterPasses) in the
// family's filter chain (add_filter_chain); the expected values come from ssss_filter.h, the header those shaders include.
#include "core/registry.hpp"
#include "graph/graph_executor.hpp"
#include "graph/pass_context.hpp"
#include "graph/graph_readback.hpp"
#include "../common/shadow_technique.hpp"
#include "render/frame_renderer.hpp"
#include "render/frame_uniforms.hpp"
#include "render/light_view.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"
#include "support/test_gpu.hpp"
#include "support/tiny_scene.hpp"

#include "shading.h"
#include "../ssss/ssss_filter.h"
#include "../ssss/ssss_params.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace canopy;
namespace sh = canopy::shader;

namespace {

// ---------------------------------------------------------------------------------------------
// Device inputs for a FilterChain.

// A float texture's texels (1 or 4 floats each, or depth), uploaded by run_passes.
struct SyntheticTexture {
    uint32_t width = 0, height = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::vector<float> texels;
};

SyntheticTexture upload_texture(MemoryLedger&, uint32_t width, uint32_t height, VkFormat format,
                                const std::vector<float>& texels) {
    return {width, height, format, texels};
}

FrameUniforms upload_uniforms(MemoryLedger&, const FrameUniforms& u) { return u; }

// What a chain's passes read besides their source: the frame uniforms (binding 2), the depth map
// (binding 3), the normals (binding 4).
struct ChainInputs {
    const FrameUniforms* frame = nullptr;
    const SyntheticTexture* shadow_depth = nullptr;
    const SyntheticTexture* normals = nullptr;
};

// Runs `passes` over `source` through the shadow family's own filter chain (add_filter_chain) in
// a frame graph of their own: a load-phase copy pass uploads the inputs, the frame runs the
// chain; the result is read back.
Image run_passes(const SyntheticTexture& source, VkFormat format, const std::vector<FilterPass>& passes,
                 const ChainInputs& inputs) {
    const GpuContext& gpu = test::gpu();
    FrameGraph graph;
    PassDecl upload{"upload_inputs", PassKind::copy, Phase::load};
    std::vector<std::pair<std::string, const SyntheticTexture*>> textures{{"source", &source}};
    if (inputs.shadow_depth) textures.push_back({"depth_map", inputs.shadow_depth});
    if (inputs.normals) textures.push_back({"normals", inputs.normals});
    for (const auto& [name, texture] : textures) {
        ImageDecl image{name, texture->format, ImageExtent::texels(texture->width, texture->height)};
        image.persistent = true;
        graph.images.push_back(image);
        upload.uses.push_back({name, Use::transfer_write});
    }
    upload.record = [textures](PassContext& pc) {
        for (const auto& [name, texture] : textures)
            pc.upload_image(name, texture->texels.data(), texture->texels.size() * sizeof(float));
    };
    graph.passes.push_back(std::move(upload));
    const std::string result =
        add_filter_chain(graph, "chain", "source", false, source.width, source.height, format, passes,
                         FilterChainInputs{inputs.frame != nullptr, inputs.shadow_depth ? "depth_map" : "",
                                           inputs.normals ? "normals" : ""},
                         false);
    MemoryLedger ledger;
    Buffer frame(gpu, ledger, "test", sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
    const FrameUniforms uniforms = inputs.frame ? *inputs.frame : FrameUniforms{};
    std::memcpy(frame.mapped(), &uniforms, sizeof(uniforms));
    const GpuScene no_geometry(gpu, ledger, Scene{}, {});
    GraphExecutor executor(gpu, ledger, std::move(graph), source.width, source.height, frame, no_geometry);
    executor.run_load(FrameState{});
    executor.run_frame(FrameState{});
    return read_graph_image(gpu, executor, result);
}

// shadow.ssss's plan for `given` parameters (the rest at their defaults).
ShadowPlan ssss_plan(const std::map<std::string, ParamValue>& given = {}) {
    const auto& ssss = dynamic_cast<const ShadowTechnique&>(*TechniqueRegistry::instance().find("shadow.ssss"));
    return ssss.plan(ParamSet::resolve(ssss.params(), given, {}, SourceLocation{}, "shadow.ssss"));
}

// The frame a rect light of width `light_width` (mean side) gives the coarse passes: a
// perspective shadow map over [near, far] whose texel spans `texel_world` at depth 1.
FrameUniforms coarse_frame(float light_width, float near_plane, float far_plane, float texel_world) {
    FrameUniforms u{};
    u.light_position = glm::vec4(0.0f, 0.0f, 0.0f, float(sh::LIGHT_RECT));
    u.light_size = glm::vec4(light_width * std::sqrt(2.0f), light_width, light_width, 0.0f);
    u.shadow_depth_range = glm::vec4(near_plane, far_plane, 1.0f / (far_plane - near_plane), 1.0f);
    u.shadow_texel = glm::vec4(0.0f, 0.0f, texel_world, 0.0f);
    return u;
}

// ---------------------------------------------------------------------------------------------
// Scenes.

struct Rendered {
    Image coarse, screen, color;
};

// One frame of shadow.ssss with `given`; the screen buffer before the blur when `without_blur`.
Rendered render_ssss(const Scene& scene, int width, int height, const std::map<std::string, ParamValue>& given,
                     bool without_blur) {
    ShadowPlan plan = ssss_plan(given);
    if (without_blur) plan.screen_shadow->filters.clear();
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), uint32_t(width), uint32_t(height),
                           shadow_graph(plan));
    renderer.render();
    return {renderer.read_image(shadow_images::coarse_map(plan)), renderer.read_image(shadow_images::screen_shadow(plan)),
            renderer.read_color()};
}

}  // namespace

// ---------------------------------------------------------------------------------------------
TEST_CASE("SSSS coarse map: each texel is the minimum of its block, partial blocks included") {
    std::mt19937 rng(62);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (long long block : {1LL, 4LL, 16LL}) {
        for (uint32_t size : {64u, 50u}) {  // 50: the last block is partial (2 of 4, or 2 of 16)
            CAPTURE(block);
            CAPTURE(size);
            std::vector<float> depth(size_t(size) * size);
            for (float& d : depth) d = u(rng);
            MemoryLedger ledger;
            const SyntheticTexture source = upload_texture(ledger, size, size, VK_FORMAT_R32_SFLOAT, depth);
            const ShadowPlan plan = ssss_plan({{"coarse_block", block}});
            const FilterPass& block_pass = plan.shadow_map->coarse_filters.front();
            REQUIRE(block_pass.downsample == block);
            const Image coarse = run_passes(source, VK_FORMAT_R32_SFLOAT, {block_pass}, {});
            const int expected_size = int((size + block - 1) / block);
            REQUIRE(coarse.width == expected_size);
            REQUIRE(coarse.height == expected_size);
            int wrong = 0;
            for (int cy = 0; cy < coarse.height; ++cy)
                for (int cx = 0; cx < coarse.width; ++cx) {
                    float lowest = 1.0f;
                    for (int y = cy * int(block); y < std::min<int>(int(size), (cy + 1) * int(block)); ++y)
                        for (int x = cx * int(block); x < std::min<int>(int(size), (cx + 1) * int(block)); ++x)
                            lowest = std::min(lowest, depth[size_t(y) * size + size_t(x)]);
                    wrong += coarse.at(cx, cy)[0] != lowest;
                }
            CHECK(wrong == 0);
            // The screen pass's lookup: shadow texel -> its block's coarse texel.
            for (int x : {0, int(block) - 1, int(block), int(size) - 1})
                CHECK(sh::ssss_coarse_texel(glm::ivec2(x, 0), int(block), glm::ivec2(expected_size)).x == x / int(block));
        }
    }
}

// L1614: "The amount of dilation is proportional to the size of the area light source [...] the
// user has to apply a constant factor [...] interpreted as the maximum distance to the occluder".
TEST_CASE("SSSS dilation: reach over the blur's support (3 sigma of eq 6.1's width), proportional to the light's size") {
    // In numbers: 3 sigma = 3 / 2.563 of eq 6.1's width on the receiver, in texels there.
    const float near_plane = 2.0f, far_plane = 6.0f, texel = 1e-3f;
    const double support = 3.0 / 2.563;
    // Blocker at 3, receiver up to 1 behind (at 4): 0.2 (4 - 3) / 3 = 1/15 on the receiver,
    // whose texels span 4e-3: 16.67 texels wide, the blur reaching 19.51 texels.
    CHECK(sh::ssss_dilation_texels(3.0f, 1.0f, far_plane, 0.2f, texel, true) == doctest::Approx(support * 16.6667).epsilon(1e-4));
    CHECK(sh::ssss_dilation_texels(3.0f, 1.0f, far_plane, 0.4f, texel, true) ==
          doctest::Approx(2.0 * sh::ssss_dilation_texels(3.0f, 1.0f, far_plane, 0.2f, texel, true)).epsilon(1e-6));
    CHECK(sh::ssss_dilation_texels(3.0f, 1.0f, far_plane, 0.0f, texel, true) == 0.0f);  // point light: none
    CHECK(sh::ssss_dilation_texels(3.0f, 0.0f, far_plane, 0.2f, texel, true) == 0.0f);  // no occluder distance
    CHECK(sh::ssss_dilation_texels(3.0f, 10.0f, far_plane, 0.2f, texel, true) ==          // receiver clamped to far
          doctest::Approx(support * 0.2 * (1.0 / 3.0 - 1.0 / 6.0) / 1e-3).epsilon(1e-4));
    CHECK(sh::ssss_dilation_texels(2.5f, 1.0f, far_plane, 0.2f, texel, true) >            // nearer blockers reach farther
          sh::ssss_dilation_texels(3.0f, 1.0f, far_plane, 0.2f, texel, true));
    CHECK(sh::ssss_dilation_texels(3.0f, 1.0f, far_plane, 0.2f, 0.01f, false) == doctest::Approx(support * 0.2 / 3.0 / 0.01).epsilon(1e-5));
    for (float d : {0.0f, 1e-30f, 1e30f})
        for (float w : {0.0f, 1e30f}) CHECK(std::isfinite(sh::ssss_dilation_texels(d, 1e30f, 1e30f, w, 0.0f, true)));
    CHECK(sh::ssss_dilation_reaches(0, 0.0f, 4));
    CHECK_FALSE(sh::ssss_dilation_reaches(1, 0.0f, 4));
    CHECK(sh::ssss_dilation_reaches(1, 0.1f, 4));
    CHECK(sh::ssss_dilation_reaches(3, 8.5f, 4));  // gap (3 - 1) 4 = 8 texels < 8.5
    CHECK_FALSE(sh::ssss_dilation_reaches(-4, 8.5f, 4));

    // On the device, through the technique's own passes: one blocker texel on an empty map
    // dilates to a square whose half-width is the largest offset its reach covers; a second,
    // farther blocker reaches less far.
    const uint32_t size = 96;
    const int block = 2;
    const float z_near = 0.25f, z_far = 0.5f;  // d_b = 3 and 4
    std::vector<float> depth(size_t(size) * size, 1.0f);
    // Coarse texel (cx, cy) covers shadow texels [2cx, 2cx + 2); put each blocker in one texel.
    auto put = [&](glm::ivec2 coarse_texel, float z) {
        depth[size_t(coarse_texel.y * block) * size + size_t(coarse_texel.x * block)] = z;
    };
    const glm::ivec2 near_coarse(15, 20), far_coarse(35, 20);
    put(near_coarse, z_near);
    put(far_coarse, z_far);
    MemoryLedger ledger;
    const SyntheticTexture source = upload_texture(ledger, size, size, VK_FORMAT_R32_SFLOAT, depth);
    const ShadowPlan plan = ssss_plan({{"coarse_block", (long long)block}, {"occluder_distance", 0.25}});
    std::vector<float> near_reaches;
    std::vector<int> near_radii;
    for (float light : {0.1f, 0.2f, 0.4f}) {
        CAPTURE(light);
        FrameUniforms uniforms = coarse_frame(light, near_plane, far_plane, texel);
        uniforms.technique = plan.shader_params.block;  // the dilation reads coarse_block, occluder_distance
        const FrameUniforms frame = upload_uniforms(ledger, uniforms);
        const Image coarse = run_passes(source, VK_FORMAT_R32_SFLOAT, plan.shadow_map->coarse_filters,
                                        ChainInputs{&frame});
        // Expected: the largest coarse offset each blocker reaches (occluder distance 0.25 x 4 = 1).
        auto reach_of = [&](float z) {
            return sh::ssss_dilation_texels(near_plane + z * (far_plane - near_plane), 1.0f, far_plane, light, texel, true);
        };
        auto radius_of = [&](float reach) {
            int r = 0;
            while (sh::ssss_dilation_reaches(r + 1, reach, block)) ++r;
            return r;
        };
        const int r_near = radius_of(reach_of(z_near)), r_far = radius_of(reach_of(z_far));
        MESSAGE("light ", light, ": the blocker at d = 3 reaches ", reach_of(z_near), " shadow texels (", r_near,
                " coarse texels), the one at d = 4 ", reach_of(z_far), " (", r_far, ")");
        CHECK(r_near > r_far);
        int wrong = 0;
        for (int y = 0; y < coarse.height; ++y)
            for (int x = 0; x < coarse.width; ++x) {
                const glm::ivec2 p(x, y);
                const glm::ivec2 dn = glm::abs(p - near_coarse), df = glm::abs(p - far_coarse);
                float expect = 1.0f;
                if (std::max(df.x, df.y) <= r_far) expect = z_far;
                if (std::max(dn.x, dn.y) <= r_near) expect = z_near;
                wrong += coarse.at(x, y)[0] != expect;
            }
        CHECK(wrong == 0);
        near_reaches.push_back(reach_of(z_near));
        near_radii.push_back(r_near);
    }
    // The reach is proportional to the light's size; the radius in whole coarse texels follows it.
    CHECK(near_reaches[1] == doctest::Approx(2.0 * near_reaches[0]).epsilon(1e-5));
    CHECK(near_reaches[2] == doctest::Approx(4.0 * near_reaches[0]).epsilon(1e-5));
    CHECK(near_radii[0] >= 2);
    CHECK(near_radii[0] < near_radii[1]);
    CHECK(near_radii[1] < near_radii[2]);
}

// The same in a rendered scene: the coarse map around the box widens with the light.
TEST_CASE("SSSS dilation in a render: the coarse map's blocker region grows with the light") {
    const int block = 4;  // the default coarse_block
    std::vector<int> widths, radii;
    for (float side : {0.2f, 0.4f, 0.8f}) {
        const Scene scene = test::tiny_scene_under_rect_light(side);
        const Rendered r = render_ssss(scene, 32, 32, {}, true);
        // The middle row of coarse texels: those nearer than the floor hold the box's top.
        int covered = 0;
        const int row = r.coarse.height / 2;
        for (int x = 0; x < r.coarse.width; ++x) covered += r.coarse.at(x, row)[0] < 0.9f;
        widths.push_back(covered);
        // The reach of the box's top (2.5 from the light) for receivers up to the default occluder
        // distance behind it (a fraction of the light's depth range), in whole coarse texels.
        const LightView lv = compute_light_view(scene.lights.front(), scene_bounds(scene, build_scene_meshes(scene)), 1024);
        const float occluder_distance = ssss_plan().shader_params.get_block<sh::SsssParams>().occluder_distance;
        const float reach = sh::ssss_dilation_texels(2.5f, occluder_distance * (lv.far_plane - lv.near_plane),
                                                     lv.far_plane, side, lv.texel_world, true);
        int radius = 0;
        while (sh::ssss_dilation_reaches(radius + 1, reach, block)) ++radius;
        radii.push_back(radius);
        MESSAGE("light side ", side, ": ", covered, " coarse texels of the middle row hold a blocker; reach ", reach,
                " shadow texels = ", radius, " coarse texels");
    }
    // The box covers the same coarse texels for every light: the growth is the dilation's, on both
    // sides.
    for (size_t i = 1; i < widths.size(); ++i) {
        CAPTURE(i);
        CHECK(radii[i] > radii[i - 1]);
        CHECK(widths[i] - widths[i - 1] == 2 * (radii[i] - radii[i - 1]));
    }
}

// ---------------------------------------------------------------------------------------------
// Eq 6.2: w = (d_receiver - d_blocker) w_light / (d_blocker d_observer).
TEST_CASE("SSSS sigma from eq 6.2, in numbers and as the screen pass writes it") {
    // d_r = 10, d_b = 5, w_light = 1, d_observer = 4: w = 5 / 20 = 0.25 per unit of distance; with
    // a focal length of 1000 pixels, 250 pixels, and sigma = 250 / 2.563.
    CHECK(sh::ssss_sigma_pixels(10.0f, 5.0f, 1.0f, 4.0f, 1000.0f) == doctest::Approx(250.0 / 2.563).epsilon(1e-6));
    CHECK(sh::ssss_sigma_pixels(10.0f, 5.0f, 2.0f, 4.0f, 1000.0f) ==
          doctest::Approx(2.0 * sh::ssss_sigma_pixels(10.0f, 5.0f, 1.0f, 4.0f, 1000.0f)));  // G-F6.9
    CHECK(sh::ssss_sigma_pixels(10.0f, 5.0f, 1.0f, 8.0f, 1000.0f) ==
          doctest::Approx(0.5 * sh::ssss_sigma_pixels(10.0f, 5.0f, 1.0f, 4.0f, 1000.0f)));  // farther: smaller
    CHECK(sh::ssss_sigma_pixels(5.0f, 5.0f, 1.0f, 4.0f, 1000.0f) == 0.0f);  // contact: no penumbra
    // 2.563 sigma is the 10-90 % rise of a blurred step: Phi(1.2816) - Phi(-1.2816) = 0.8.
    const double half = 0.5 * sh::SSSS_PENUMBRA_WIDTH_IN_SIGMAS / std::sqrt(2.0);
    CHECK(0.5 * (std::erf(half) - std::erf(-half)) == doctest::Approx(0.8).epsilon(1e-4));
    // Anisotropy: a normal along view x shrinks x entirely, one tilted 45 degrees in y by sqrt(1/2).
    CHECK(sh::ssss_anisotropic_sigma(2.0f, {1.0f, 0.0f, 0.0f}) == glm::vec2(0.0f, 2.0f));
    CHECK(sh::ssss_anisotropic_sigma(2.0f, {0.0f, std::sqrt(0.5f), std::sqrt(0.5f)}).y == doctest::Approx(std::sqrt(2.0)));

    // The screen pass, in the box scene: floor pixels under the box get eq 6.2 with the coarse
    // map's blocker (the box top at y = 1.5: 2.5 from the light), the floor 4 from the light,
    // their own distance to the camera and the camera's focal length.
    const int width = 96, height = 64;
    const float side = 0.2f;
    const Scene scene = test::tiny_scene_under_rect_light(side);
    const Rendered r = render_ssss(scene, width, height, {}, true);
    const float focal = 0.5f * float(height) / std::tan(0.5f * glm::radians(scene.camera.fov_y_degrees));
    const glm::mat4 view = view_matrix(scene.camera);
    const glm::vec3 floor_normal_view = glm::normalize(glm::mat3(view) * glm::vec3(0.0f, 1.0f, 0.0f));
    int checked = 0, wrong = 0;
    for (glm::vec3 target : {glm::vec3(0.0f), glm::vec3(0.2f, 0.0f, 0.1f), glm::vec3(-0.3f, 0.0f, -0.2f)}) {
        const glm::vec2 px = project_to_pixel(scene.camera, width, height, target);
        const int x = int(px.x), y = int(px.y);
        const Ray ray = primary_ray(scene.camera, width, height, float(x) + 0.5f, float(y) + 0.5f);
        const glm::vec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);  // on the floor
        const float d_observer = glm::length(p - scene.camera.position);
        const float view_depth = -(view * glm::vec4(p, 1.0f)).z;  // eq 6.2's Z
        const float sigma = sh::ssss_sigma_pixels(4.0f, 2.5f, side, view_depth, focal);
        const glm::vec2 expect = sh::ssss_anisotropic_sigma(sigma, floor_normal_view);
        const float* data = r.screen.at(x, y);
        CAPTURE(x);
        CAPTURE(y);
        CHECK(data[0] == 0.0f);  // under the box: hard shadow
        CHECK(data[1] == doctest::Approx(expect.x).epsilon(2e-3));
        CHECK(data[2] == doctest::Approx(expect.y).epsilon(2e-3));
        CHECK(data[3] == doctest::Approx(d_observer).epsilon(1e-4));
        ++checked;
        wrong += !(std::abs(data[1] - expect.x) <= 2e-3f * expect.x);
    }
    CHECK(checked == 3);
    CHECK(wrong == 0);
    // The open floor's corner, far from any blocker: sigma 0 (the mask).
    const glm::vec2 open = project_to_pixel(scene.camera, width, height, glm::vec3(-2.5f, 0.0f, 2.0f));
    CHECK(r.screen.at(int(open.x), int(open.y))[1] == 0.0f);
    CHECK(r.screen.at(int(open.x), int(open.y))[0] == 1.0f);
}

// ---------------------------------------------------------------------------------------------
TEST_CASE("SSSS blur taps: whole pixels, each once, weighted by the Gaussian of its offset") {
    for (int taps : {5, 11, 23, 4}) {
        for (float sigma : {0.25f, 0.4f, 0.5f, 0.8f, 1.0f, 1.7f, 3.0f, 6.0f, 20.0f}) {
            CAPTURE(taps);
            CAPTURE(sigma);
            std::vector<int> offsets;
            double sum = 0.0, second = 0.0;
            for (int i = 0; i < taps; ++i) {
                const int o = sh::ssss_tap_offset(i, taps, sigma);
                offsets.push_back(o);
                const double w = sh::ssss_tap_weight(o, sigma);
                CHECK(w == doctest::Approx(std::exp(-0.5 * double(o) * o / (double(sigma) * sigma))));
                sum += w;
                second += w * double(o) * o;
            }
            std::vector<int> sorted = offsets;
            std::sort(sorted.begin(), sorted.end());
            CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());  // no pixel twice
            for (int i = 0; i < taps; ++i) CHECK(offsets[size_t(i)] == -offsets[size_t(taps - 1 - i)]);  // symmetric
            if (taps % 2 == 1) CHECK(offsets[size_t(taps / 2)] == 0);
            // The kernel spans +-3 sigma (or +-(taps - 1) / 2 pixels when that is wider).
            CHECK(double(sorted.back()) >= std::min(3.0 * sigma, 0.5 * (taps - 1)) - 0.5);
            // Its variance is sigma^2 where the taps resolve the Gaussian (at least one per sigma):
            // a sampled Gaussian, not the rounded kernel's (1.5 sigma^2 at sigma 0.5, K = 11).
            const double variance = second / sum;
            if (taps >= 11 && sigma >= 0.5f && sigma <= float(taps - 1) / 6.0f) {
                CHECK(variance == doctest::Approx(double(sigma) * sigma).epsilon(0.15));
            }
        }
    }
}

// Extremes: a sigma from eq 6.2 near d_blocker = 0 is huge, one at contact 0; both stay usable.
TEST_CASE("SSSS sigma and taps at extremes stay finite") {
    for (float d_b : {0.0f, 1e-30f, 1.0f, 1e30f})
        for (float w : {0.0f, 1.0f, 1e30f})
            for (float d_obs : {0.0f, 1.0f, 1e30f}) {
                const float sigma = sh::ssss_sigma_pixels(10.0f, d_b, w, d_obs, 1000.0f);
                CHECK_MESSAGE((std::isfinite(sigma) && sigma >= 0.0f), "sigma ", sigma);
            }
    for (float sigma : {0.0f, 1e-30f, 1e30f, std::numeric_limits<float>::infinity()}) {
        CAPTURE(sigma);
        for (int i = 0; i < 11; ++i) {
            const int o = sh::ssss_tap_offset(i, 11, sigma);
            CHECK(std::abs(o) <= 1000000);
            CHECK(o == -sh::ssss_tap_offset(10 - i, 11, sigma));
            const float w = sh::ssss_tap_weight(o, sigma);
            CHECK((std::isfinite(w) && w >= 0.0f && w <= 1.0f));
        }
        CHECK(sh::ssss_tap_weight(0, sigma) == 1.0f);  // the centre always counts
    }
}

namespace {

// A synthetic screen for the blur: a camera at (0, 0, 5) looking down -z at a floor (the plane
// z = 0, normal +z) which a light straight above (orthographic over [-5, 5]^2, along -z) shadows
// for world x < kShadowEdge, through a 64^2 shadow map whose first 30 columns hold a blocker at
// depth 0.1. The edge is off the camera's axis, so where along a view ray a point is matters.
struct BlurScreen {
    static constexpr int kWidth = 64, kHeight = 8;
    static constexpr int kBlockerColumns = 30;
    static constexpr float kShadowEdge = -5.0f + 10.0f * float(kBlockerColumns) / 64.0f;  // -0.3125
    FrameUniforms frame{};
    glm::vec3 camera{0.0f, 0.0f, 5.0f};
    glm::mat4 inverse_view_proj{1.0f};

    BlurScreen() {
        const glm::mat4 view = glm::lookAt(camera, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        // 8 rows over 10 degrees: about 70 degrees across, so the floor's distance changes by up
        // to 22 % along a row, up to ~1.3 % from one pixel to the next (the depth test's threshold
        // is 5 %, of the distance predicted by the tangent plane).
        const glm::mat4 proj = glm::perspective(glm::radians(10.0f), float(kWidth) / float(kHeight), 0.1f, 100.0f);
        frame.view = view;
        frame.view_proj = proj * view;
        frame.inverse_view_proj = inverse_view_proj = glm::inverse(proj * view);
        frame.camera_position = glm::vec4(camera, 1.0f);
        frame.light_position = glm::vec4(0.0f, 0.0f, 10.0f, float(sh::LIGHT_DIRECTIONAL));
        frame.light_axis = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f);
        frame.light_view = glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        frame.light_proj = glm::ortho(-5.0f, 5.0f, -5.0f, 5.0f, 1.0f, 20.0f);
        frame.shadow_depth_range = glm::vec4(1.0f, 20.0f, 1.0f / 19.0f, 0.0f);
        frame.shadow_texel = glm::vec4(64.0f, 1.0f / 64.0f, 10.0f / 64.0f, 0.0f);
    }
    // The view ray through pixel (x, y), as ssss_blur.comp's pixel_ray forms it.
    glm::vec3 ray(int x, int y) const {
        const glm::vec2 ndc = (glm::vec2(float(x), float(y)) + 0.5f) / glm::vec2(kWidth, kHeight) * 2.0f - 1.0f;
        const glm::vec4 far_point = inverse_view_proj * glm::vec4(ndc, 1.0f, 1.0f);
        return glm::normalize(glm::vec3(far_point) / far_point.w - camera);
    }
    // Distance along pixel (x, y)'s ray to the plane through the origin with normal n (the floor:
    // n = +z).
    float plane_distance(int x, int y, glm::vec3 n) const { return -glm::dot(n, camera) / glm::dot(n, ray(x, y)); }
    float floor_distance(int x, int y) const { return plane_distance(x, y, {0.0f, 0.0f, 1.0f}); }
    static bool shadowed(const glm::vec3& p) { return p.x < kShadowEdge; }
    bool floor_shadowed(int x, int y) const { return shadowed(camera + ray(x, y) * floor_distance(x, y)); }
};

// The blur's horizontal pass over `data` (per pixel: hard, sigma_x, sigma_y, distance) with the
// technique's own parameters, on the device; the normal buffer holds `normal` everywhere.
Image blur_x(const BlurScreen& screen, const std::vector<float>& data, const std::map<std::string, ParamValue>& given,
             glm::vec3 normal = {0.0f, 0.0f, 1.0f}) {
    MemoryLedger ledger;
    const SyntheticTexture source = upload_texture(ledger, BlurScreen::kWidth, BlurScreen::kHeight, VK_FORMAT_R32G32B32A32_SFLOAT, data);
    std::vector<float> normals;
    for (int i = 0; i < BlurScreen::kWidth * BlurScreen::kHeight; ++i) normals.insert(normals.end(), {normal.x, normal.y, normal.z, 1.0f});
    const SyntheticTexture normal_map = upload_texture(ledger, BlurScreen::kWidth, BlurScreen::kHeight, VK_FORMAT_R32G32B32A32_SFLOAT, normals);
    std::vector<float> depth(64 * 64, 1.0f);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < BlurScreen::kBlockerColumns; ++x) depth[size_t(y) * 64 + size_t(x)] = 0.1f;
    const SyntheticTexture shadow_map = upload_texture(ledger, 64, 64, VK_FORMAT_D32_SFLOAT, depth);
    const ShadowPlan plan = ssss_plan(given);
    FrameUniforms uniforms = screen.frame;
    uniforms.technique = plan.shader_params.block;  // taps, depth_error, lazy and the bias
    const FrameUniforms frame = upload_uniforms(ledger, uniforms);
    const FilterPass& pass = plan.screen_shadow->filters.front();
    REQUIRE(pass.horizontal);
    return run_passes(source, VK_FORMAT_R32G32B32A32_SFLOAT, {pass},
                      ChainInputs{&frame, &shadow_map, &normal_map});
}

// ssss_blur.comp's horizontal pass at pixel (x, y) in C++, from ssss_filter.h: `data` as uploaded,
// `normal` the normal buffer's. A tap is tested against the distance at which the ray of the pixel
// it reads (clamped to the image) meets the centre's tangent plane; a hidden tap with lazy
// shadowing reads the light's shadow where its own ray meets that plane.
float expected_blur(const BlurScreen& screen, const std::vector<float>& data, int x, int y, int taps, float depth_error,
                    bool lazy, glm::vec3 normal = {0.0f, 0.0f, 1.0f}) {
    auto texel = [&](int tx) { return &data[(size_t(y) * BlurScreen::kWidth + size_t(tx)) * 4]; };
    const float* centre = texel(x);
    const float sigma = centre[1];
    if (!sh::ssss_blurs(sigma, centre[3])) return centre[0];
    const glm::vec3 centre_from_camera = screen.ray(x, y) * centre[3];
    float sum = 0.0f, weights = 0.0f;
    for (int i = 0; i < taps; ++i) {
        const int o = sh::ssss_tap_offset(i, taps, sigma);
        const int tx = std::clamp(x + o, 0, BlurScreen::kWidth - 1);
        float value = texel(tx)[0];
        const float expected = sh::ssss_expected_distance(normal, screen.ray(tx, y), centre_from_camera, centre[3]);
        if (!sh::ssss_same_surface(texel(tx)[3], expected, depth_error)) {
            if (!lazy) continue;
            const glm::vec3 ray = screen.ray(x + o, y);
            const float t = sh::ssss_tangent_plane_distance(normal, ray, centre_from_camera);
            if (t <= 0.0f) continue;
            value = BlurScreen::shadowed(screen.camera + ray * t) ? 0.0f : 1.0f;
        }
        const float w = sh::ssss_tap_weight(o, sigma);
        sum += w * value;
        weights += w;
    }
    return weights > 0.0f ? sum / weights : centre[0];
}

// The plain Gaussian of the pass at pixel (x, y): every tap kept, whatever its distance.
float gaussian_blur(const std::vector<float>& data, int x, int y, int taps) {
    auto texel = [&](int tx) { return &data[(size_t(y) * BlurScreen::kWidth + size_t(std::clamp(tx, 0, BlurScreen::kWidth - 1))) * 4]; };
    const float sigma = texel(x)[1];
    float sum = 0.0f, weights = 0.0f;
    for (int i = 0; i < taps; ++i) {
        const int o = sh::ssss_tap_offset(i, taps, sigma);
        const float w = sh::ssss_tap_weight(o, sigma);
        sum += w * texel(x + o)[0];
        weights += w;
    }
    return sum / weights;
}

}  // namespace

// 6.2.3: "their distance to the observer is taken into account to discard samples whose distance
// to the current pixel is greater than a certain threshold".
TEST_CASE("SSSS blur on the device: Gaussian taps, and taps across a depth jump are excluded") {
    const BlurScreen screen;
    const float sigma = 3.0f;
    const int taps = 11;
    // Columns 0-19: another surface, `far_factor` times as far, in shadow (0); the rest the floor, lit (1).
    auto make = [&](float far_factor) {
        std::vector<float> data;
        for (int y = 0; y < BlurScreen::kHeight; ++y)
            for (int x = 0; x < BlurScreen::kWidth; ++x) {
                const float d = screen.floor_distance(x, y);
                data.insert(data.end(), {x < 20 ? 0.0f : 1.0f, sigma, sigma, x < 20 ? far_factor * d : d});
            }
        return data;
    };
    // No jump: the plain Gaussian across the step (every tap on the floor, the centre's tangent plane).
    const std::vector<float> flat = make(1.0f), stepped = make(2.0f);
    const Image plain = blur_x(screen, flat, {{"kernel", (long long)taps}, {"lazy", false}});
    // A jump of 100 % (> depth_error 5 %): each side ignores the other's taps.
    const Image jump = blur_x(screen, stepped, {{"kernel", (long long)taps}, {"lazy", false}});
    int plain_wrong = 0, jump_wrong = 0, darkened = 0;
    for (int y = 0; y < BlurScreen::kHeight; ++y)
        for (int x = 0; x < BlurScreen::kWidth; ++x) {
            plain_wrong += std::abs(plain.at(x, y)[0] - expected_blur(screen, flat, x, y, taps, 0.05f, false)) > 1e-5f;
            plain_wrong += std::abs(plain.at(x, y)[0] - gaussian_blur(flat, x, y, taps)) > 1e-5f;
            jump_wrong += std::abs(jump.at(x, y)[0] - expected_blur(screen, stepped, x, y, taps, 0.05f, false)) > 1e-5f;
            darkened += x >= 20 && plain.at(x, y)[0] < 0.99f;
        }
    CHECK(plain_wrong == 0);
    CHECK(jump_wrong == 0);
    CHECK(darkened >= 4 * BlurScreen::kHeight);  // without the jump the step is blurred across
    const int y = 3;
    for (int x = 0; x < BlurScreen::kWidth; ++x) CHECK(jump.at(x, y)[0] == (x < 20 ? 0.0f : 1.0f));  // own taps only
    // Sigma and distance pass through untouched.
    CHECK(jump.at(30, y)[1] == sigma);
    CHECK(jump.at(30, y)[3] == doctest::Approx(screen.floor_distance(30, y)));
}

// 6.2.3 and 6.3.2: the paper compares |z_tap - z_ref| with errDepth (Algorithm 4) and assumes the
// surface locally planar (lazy shadowing). canopy tests a tap against where its view ray meets the
// centre's tangent plane, relative to that distance (README: the depth test), so the centre's own
// surface is kept however much its distance changes across the kernel, and a depth jump is not.
TEST_CASE("SSSS depth test: a tap is compared with where its ray meets the centre's tangent plane") {
    const glm::vec3 up(0.0f, 0.0f, 1.0f), below(0.0f, 0.0f, -5.0f);  // the floor, 5 below the camera
    const float cos60 = 0.5f, sin60 = std::sqrt(0.75f);
    const glm::vec3 oblique(sin60, 0.0f, -cos60);
    // 60 degrees off the vertical the floor is twice as far as straight below: 10, not 5.
    const float expected = sh::ssss_expected_distance(up, oblique, below, 5.0f);
    CHECK(expected == doctest::Approx(10.0f).epsilon(1e-6));
    CHECK(sh::ssss_same_surface(10.0f, expected, 0.05f));
    CHECK(sh::ssss_same_surface(10.45f, expected, 0.05f));  // 4.5 % of the prediction (9 % of the centre's 5)
    CHECK(sh::ssss_same_surface(9.55f, expected, 0.05f));
    CHECK_FALSE(sh::ssss_same_surface(10.6f, expected, 0.05f));  // 6 %: a step of the surface
    CHECK_FALSE(sh::ssss_same_surface(9.4f, expected, 0.05f));
    CHECK_FALSE(sh::ssss_same_surface(5.0f, expected, 0.05f));   // the centre's distance is not the floor there
    CHECK_FALSE(sh::ssss_same_surface(20.0f, expected, 0.05f));  // a depth jump
    CHECK(sh::ssss_same_surface(10.6f, expected, 0.1f));
    // A ray that misses the plane (grazing, or away from it) falls back to the centre's distance.
    CHECK(sh::ssss_expected_distance(up, {1.0f, 0.0f, 0.0f}, below, 5.0f) == 5.0f);
    CHECK(sh::ssss_expected_distance(up, {0.0f, 0.0f, 1.0f}, below, 5.0f) == 5.0f);
    CHECK(sh::ssss_same_surface(5.2f, 5.0f, 0.05f));
    CHECK_FALSE(sh::ssss_same_surface(5.3f, 5.0f, 0.05f));
    // Extremes: the expected distance is a positive, finite one or the centre's own; an infinite
    // or NaN distance (tap or expected) is never the same surface.
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (glm::vec3 n : {up, glm::vec3(0.0f), glm::vec3(nan, 0.0f, 1.0f), glm::vec3(1e-30f, 0.0f, 0.0f)})
        for (glm::vec3 ray : {glm::vec3(0.0f, 0.0f, -1.0f), oblique, glm::vec3(1.0f, 0.0f, -1e-6f)})
            for (float d : {0.0f, 1e-30f, 1.0f, 1e30f, 3e38f, inf, nan}) {
                CAPTURE(n);
                CAPTURE(ray);
                CAPTURE(d);
                const float e = sh::ssss_expected_distance(n, ray, glm::vec3(0.0f, 0.0f, -1.0f) * d, d);
                CHECK((e == d || (std::isnan(d) && std::isnan(e)) || (e > 0.0f && e < 1e30f)));
                for (float tap : {inf, -inf, nan}) {
                    CHECK_FALSE(sh::ssss_same_surface(tap, e, 0.05f));
                    CHECK_FALSE(sh::ssss_same_surface(tap, e, 1.0f));
                }
                if (!std::isfinite(e)) CHECK_FALSE(sh::ssss_same_surface(1.0f, e, 1.0f));
            }
    CHECK_FALSE(sh::ssss_same_surface(1.0f, 1.0f, nan));

    // On the device: a wide kernel (sigma 8: taps up to 24 pixels away) over the floor and over a
    // tilted plane, whose distances change by far more than 5 % across it. Every tap lies on the
    // centre's tangent plane: the blur is the plain Gaussian, with lazy shadowing or without (a
    // tap wrongly taken for another surface would be dropped, or re-tested against the shadow map,
    // whose edge is 9 columns from the data's).
    const BlurScreen screen;
    const float sigma = 8.0f;
    const int taps = 11, y = 3;
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.6f, 0.0f, 0.8f));
    auto make = [&](glm::vec3 n) {
        std::vector<float> data;
        for (int yy = 0; yy < BlurScreen::kHeight; ++yy)
            for (int x = 0; x < BlurScreen::kWidth; ++x)
                data.insert(data.end(), {x < 20 ? 0.0f : 1.0f, sigma, sigma, screen.plane_distance(x, yy, n)});
        return data;
    };
    for (glm::vec3 n : {up, tilted}) {
        CAPTURE(n);
        const std::vector<float> data = make(n);
        // Algorithm 4's test against the centre's distance would drop taps here.
        int far_taps = 0;
        for (int i = 0; i < taps; ++i) {
            const int tx = std::clamp(32 + sh::ssss_tap_offset(i, taps, sigma), 0, BlurScreen::kWidth - 1);
            far_taps += std::abs(screen.plane_distance(tx, y, n) - screen.plane_distance(32, y, n)) > 0.05f * screen.plane_distance(32, y, n);
        }
        REQUIRE(far_taps >= 2);
        for (bool lazy : {false, true}) {
            CAPTURE(lazy);
            const Image out = blur_x(screen, data, {{"kernel", (long long)taps}, {"lazy", lazy}}, n);
            int wrong = 0, blurred = 0;
            for (int x = 0; x < BlurScreen::kWidth; ++x) {
                wrong += std::abs(out.at(x, y)[0] - gaussian_blur(data, x, y, taps)) > 1e-5f;
                blurred += out.at(x, y)[0] > 0.01f && out.at(x, y)[0] < 0.99f;
            }
            CHECK(wrong == 0);
            CHECK(blurred >= 30);  // the step spreads over +-3 sigma
        }
    }
    // The normal buffer decides: told the tilted plane is the floor, the blur finds its far taps
    // off the floor's plane and drops them (ssss_filter.h's rule, evaluated in C++).
    const std::vector<float> data = make(tilted);
    double margin = 1.0;  // how far each tap's relative difference is from the threshold
    for (int x = 0; x < BlurScreen::kWidth; ++x)
        for (int i = 0; i < taps; ++i) {
            const int tx = std::clamp(x + sh::ssss_tap_offset(i, taps, sigma), 0, BlurScreen::kWidth - 1);
            const float e = sh::ssss_expected_distance(up, screen.ray(tx, y), screen.ray(x, y) * data[(size_t(y) * BlurScreen::kWidth + size_t(x)) * 4 + 3],
                                                       screen.plane_distance(x, y, tilted));
            margin = std::min(margin, std::abs(std::abs(screen.plane_distance(tx, y, tilted) - e) / e - 0.05));
        }
    REQUIRE(margin > 1e-4);  // no tap so near the threshold that float rounding could flip it
    const Image misled = blur_x(screen, data, {{"kernel", (long long)taps}, {"lazy", false}}, up);
    int wrong = 0, differs = 0;
    for (int x = 0; x < BlurScreen::kWidth; ++x) {
        wrong += std::abs(misled.at(x, y)[0] - expected_blur(screen, data, x, y, taps, 0.05f, false, up)) > 1e-5f;
        differs += std::abs(misled.at(x, y)[0] - gaussian_blur(data, x, y, taps)) > 0.01f;
    }
    CHECK(wrong == 0);
    CHECK(differs >= 4);
}

// 6.3.2: a tap hidden by a nearer surface is replaced by the hard shadow of the point where its
// view ray meets the centre pixel's tangent plane.
TEST_CASE("SSSS lazy shadowing on the device: hidden taps take the shadow of the tangent plane") {
    const BlurScreen screen;
    const float sigma = 4.0f;
    const int taps = 11;
    // Columns 0-31 show a nearer, lit object (distance 2, not blurred: sigma 0); behind it the
    // floor continues into the light's shadow (world x < -0.3125). Columns 32+ show the lit floor.
    std::vector<float> data;
    for (int y = 0; y < BlurScreen::kHeight; ++y)
        for (int x = 0; x < BlurScreen::kWidth; ++x) {
            const bool object = x < 32;
            data.insert(data.end(), {1.0f, object ? 0.0f : sigma, object ? 0.0f : sigma,
                                     object ? 2.0f : screen.floor_distance(x, y)});
        }
    REQUIRE(screen.floor_shadowed(26, 3));  // hidden behind the object, in the light's shadow
    REQUIRE_FALSE(screen.floor_shadowed(31, 3));  // hidden, lit
    REQUIRE_FALSE(screen.floor_shadowed(32, 3));
    const Image lazy = blur_x(screen, data, {{"kernel", (long long)taps}, {"lazy", true}});
    const Image dropped = blur_x(screen, data, {{"kernel", (long long)taps}, {"lazy", false}});
    const int y = 3;
    int wrong = 0, darker = 0;
    for (int x = 32; x < BlurScreen::kWidth; ++x) {
        // Hidden taps (x < 32) read the floor's shadow behind the object: 0 beyond the edge.
        wrong += std::abs(lazy.at(x, y)[0] - expected_blur(screen, data, x, y, taps, 0.05f, true)) > 1e-4f;
        darker += lazy.at(x, y)[0] < 0.99f;
        CHECK(dropped.at(x, y)[0] == 1.0f);  // without lazy shadowing: only the visible, lit floor
    }
    CHECK(wrong == 0);
    CHECK(darker >= 4);  // the penumbra the object hides from view reappears beside it
    // The object's own pixels (sigma 0) are left alone.
    for (int x = 0; x < 32; ++x) CHECK(lazy.at(x, y)[0] == 1.0f);
    // Tangent-plane distances in numbers: a ray along -z meets the plane z = 0 at 5 from z = 5.
    CHECK(sh::ssss_tangent_plane_distance({0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, -5.0f}) == 5.0f);
    CHECK(sh::ssss_tangent_plane_distance({0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -5.0f}) < 0.0f);  // grazing
    CHECK(sh::ssss_tangent_plane_distance({0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -5.0f}) < 0.0f);  // behind
}

// 6.2.2's mask: pixels that no penumbra can reach skip the blur. Skipping must not change what
// the blur would give there, and it does not, since such pixels see only their own value; nor do
// fully lit or fully shadowed neighbourhoods change when blurred.
TEST_CASE("SSSS mask: skipped pixels keep their value, and fully lit or shadowed ones would anyway") {
    const BlurScreen screen;
    const int y = 2;
    for (float hard : {0.0f, 1.0f}) {
        for (float sigma : {0.0f, 0.2f, 3.0f}) {
            std::vector<float> data;
            for (int yy = 0; yy < BlurScreen::kHeight; ++yy)
                for (int x = 0; x < BlurScreen::kWidth; ++x)
                    data.insert(data.end(), {hard, sigma, sigma, screen.floor_distance(x, yy)});
            const Image out = blur_x(screen, data, {{"lazy", false}});  // (lazy re-reads the synthetic shadow map)
            CAPTURE(hard);
            CAPTURE(sigma);
            for (int x = 0; x < BlurScreen::kWidth; ++x) CHECK(out.at(x, y)[0] == hard);
        }
    }
    // A masked pixel (sigma 0, or below 0.25) beside a shadow edge stays as it is; the background
    // (distance 1e30) too.
    std::vector<float> data;
    for (int yy = 0; yy < BlurScreen::kHeight; ++yy)
        for (int x = 0; x < BlurScreen::kWidth; ++x) {
            const float s = x == 20 ? 0.0f : x == 21 ? 0.2f : 3.0f;
            data.insert(data.end(), {x < 20 ? 0.0f : 1.0f, s, s, x == 40 ? 1e30f : screen.floor_distance(x, yy)});
        }
    const Image out = blur_x(screen, data, {{"lazy", false}});
    CHECK(out.at(20, y)[0] == 1.0f);
    CHECK(out.at(21, y)[0] == 1.0f);
    CHECK(out.at(22, y)[0] < 1.0f);  // blurred: its taps reach the shadow
    CHECK(out.at(40, y)[0] == 1.0f);
    CHECK(out.at(40, y)[3] == 1e30f);
    CHECK(sh::ssss_blurs(0.25f, 10.0f));
    CHECK_FALSE(sh::ssss_blurs(0.2f, 10.0f));
    CHECK_FALSE(sh::ssss_blurs(3.0f, 1e30f));
}
