#include "reference/reference_renderer.hpp"

#include "reference/pixel_integrator.hpp"
#include "reference/tiled_trace.hpp"

#include <fmt/format.h>

#include <chrono>
#include <stdexcept>

namespace canopy {

namespace {

void check_arguments(int width, int height, const ReferenceSettings& settings) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument(fmt::format("render_reference: image size {}x{} is empty", width, height));
    if (settings.light_samples < 1 || settings.pixel_samples < 1)
        throw std::invalid_argument(fmt::format("render_reference: light_samples ({}) and pixel_samples ({}) must be >= 1",
                                                settings.light_samples, settings.pixel_samples));
}

}  // namespace

ReferenceImages render_reference(const Scene& scene, const std::vector<TriangleMesh>& meshes, int width,
                                 int height, const ReferenceSettings& settings,
                                 const std::function<void(double)>& progress) {
    check_arguments(width, height, settings);
    const auto start = std::chrono::steady_clock::now();
    const EmbreeScene embree(scene, meshes);
    ReferenceImages images = render_reference(scene, embree, width, height, settings, progress);
    images.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return images;
}

ReferenceImages render_reference(const Scene& scene, const EmbreeScene& embree, int width, int height,
                                 const ReferenceSettings& settings, const std::function<void(double)>& progress) {
    check_arguments(width, height, settings);
    const auto start = std::chrono::steady_clock::now();
    const PixelIntegrator integrator(scene, embree, width, height, settings);

    ReferenceImages images;
    images.radiance = Image(width, height);
    images.variance = Image(width, height);
    images.visibility = Image(width, height);

    images.shadow_rays = trace_tiles(width, height, settings.threads, embree.shadow_scene(), embree.shadow_query(), progress,
                                     [&](int x, int y, EmbreeShadowTracer& tracer) {
        const PixelEstimate pixel = integrator.integrate(x, y, tracer);
        float* radiance = images.radiance.at(x, y);
        float* variance = images.variance.at(x, y);
        float* visibility = images.visibility.at(x, y);
        for (int c = 0; c < 3; ++c) {
            radiance[c] = pixel.radiance[c];
            variance[c] = pixel.variance[c];
        }
        radiance[3] = variance[3] = 1.0f;
        visibility[0] = pixel.visible_fraction;
        visibility[1] = pixel.facing;
        visibility[2] = pixel.population_coverage;
        visibility[3] = 1.0f;
    }, 0.0, settings.rows);

    images.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return images;
}

}  // namespace canopy
