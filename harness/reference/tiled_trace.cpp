#include "reference/tiled_trace.hpp"

#include "reference/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>

namespace canopy {

namespace {
constexpr int kTileSize = 16;  // pixels per side: coherent primary rays, cheap to hand out
}

uint64_t trace_tiles(int width, int height, int threads, RTCScene shadow_scene,
                     const std::function<void(double fraction_done)>& progress,
                     const std::function<void(int x, int y, EmbreeShadowTracer& tracer)>& pixel) {
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles_y = (height + kTileSize - 1) / kTileSize;
    const size_t tile_count = size_t(tiles_x) * size_t(tiles_y);
    std::atomic<uint64_t> shadow_rays{0};
    size_t tiles_done = 0;
    std::mutex progress_mutex;
    parallel_for(tile_count, threads, [&](size_t tile, int) {
        const int x0 = int(tile % size_t(tiles_x)) * kTileSize, y0 = int(tile / size_t(tiles_x)) * kTileSize;
        const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
        EmbreeShadowTracer tracer(shadow_scene);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) pixel(x, y, tracer);
        shadow_rays += tracer.rays();
        if (progress) {
            std::lock_guard lock(progress_mutex);
            progress(double(++tiles_done) / double(tile_count));
        }
    });
    return shadow_rays;
}

}  // namespace canopy
