#include "reference/pixel_visibility.hpp"

#include "reference/light_integrator.hpp"
#include "reference/light_sampling.hpp"
#include "reference/primary_hit.hpp"
#include "reference/sample_patterns.hpp"
#include "reference/tiled_trace.hpp"
#include "scene/camera.hpp"

#include <fmt/format.h>

#include <chrono>
#include <stdexcept>

namespace canopy {

namespace {

constexpr uint64_t kSampleDomain = 0x5c3e7e4du;  // keeps these samples apart from the radiance reference's

}  // namespace

PixelVisibilityRender render_pixel_visibility(const Scene& scene, const EmbreeScene& embree, int width, int height,
                                              const PixelVisibilitySettings& settings,
                                              const std::function<void(double)>& progress) {
    namespace pv = pixel_visibility;
    if (width <= 0 || height <= 0)
        throw std::invalid_argument(fmt::format("render_pixel_visibility: image size {}x{} is empty", width, height));
    if (settings.light_samples < 1)
        throw std::invalid_argument(
            fmt::format("render_pixel_visibility: light_samples ({}) must be >= 1", settings.light_samples));
    check_camera_representable(scene);
    const auto start = std::chrono::steady_clock::now();
    std::vector<PreparedLight> lights = prepare_lights(scene, settings.light_samples, settings.seed);
    limit_shadow_reach(lights, embree.extent());
    const Light* shadow_light = scene.shadow_light();
    const PreparedLight* light = shadow_light ? &lights[size_t(shadow_light - scene.lights.data())] : nullptr;
    const Camera& camera = scene.camera;
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);

    PixelVisibilityRender result;
    result.visibility = Image(width, height);
    result.shadow_rays = trace_tiles(width, height, settings.threads, embree.shadow_scene(), embree.shadow_query(), progress,
                                     [&](int x, int y, EmbreeShadowTracer& tracer) {
        float* out = result.visibility.at(x, y);
        const Ray ray = primary_ray(camera, width, height, float(x) + settings.position_in_pixel_x,
                                    float(y) + settings.position_in_pixel_y);
        const std::optional<PrimaryHit> hit = trace_primary(embree, camera, forward, ray);
        out[pv::kVisibility] = pv::kNotLit;
        if (!hit) return;  // background: depth 0, no surface
        out[pv::kViewDepth] = hit->view_depth;
        out[pv::kSurface] = 1.0f;
        if (!light) return;
        const uint64_t pixel = uint64_t(y) * uint64_t(width) + uint64_t(x);
        const LightEstimate estimate =
            integrate_light(*light, hit->surface, random_key(settings.seed, kSampleDomain, pixel), false, tracer);
        out[pv::kVisibility] = estimate.weighted_visibility >= 0.0f ? estimate.weighted_visibility : pv::kNotLit;
    }, 0.0, settings.rows);

    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace canopy
