#include "reference/reference_renderer.hpp"

#include "reference/parallel_for.hpp"
#include "reference/pixel_integrator.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>

namespace canopy {

namespace {

constexpr int kTileSize = 16;

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

    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles_y = (height + kTileSize - 1) / kTileSize;
    const size_t tile_count = size_t(tiles_x) * size_t(tiles_y);
    std::atomic<uint64_t> shadow_rays{0};
    size_t tiles_done = 0;
    std::mutex progress_mutex;

    parallel_for(tile_count, settings.threads, [&](size_t tile, int) {
        const int x0 = int(tile % size_t(tiles_x)) * kTileSize, y0 = int(tile / size_t(tiles_x)) * kTileSize;
        const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
        EmbreeShadowTracer tracer(embree.shadow_scene());
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
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
                visibility[2] = 0.0f;
                visibility[3] = 1.0f;
            }
        }
        shadow_rays += tracer.rays();
        if (progress) {
            std::lock_guard lock(progress_mutex);  // serialised and monotonic
            progress(double(++tiles_done) / double(tile_count));
        }
    });

    images.shadow_rays = shadow_rays;
    images.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return images;
}

}  // namespace canopy
