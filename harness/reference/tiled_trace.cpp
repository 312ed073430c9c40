#include "reference/tiled_trace.hpp"

#include "reference/parallel_for.hpp"
#include "reference/stall_watch.hpp"
#include "run/interrupt.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <mutex>

namespace canopy {

namespace {
constexpr int kTileSize = 16;  // pixels per side: coherent primary rays, cheap to hand out
}

uint64_t trace_tiles(int width, int height, int threads, RTCScene shadow_scene, ShadowQuery query,
                     const std::function<void(double fraction_done)>& progress,
                     const std::function<void(int x, int y, EmbreeShadowTracer& tracer)>& pixel, double stall_seconds,
                     RowBand rows) {
    const int row_begin = std::clamp(rows.begin, 0, height);
    const int row_end = rows.end < 0 ? height : std::clamp(rows.end, row_begin, height);
    const int first_tile_row = row_begin / kTileSize;
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles_y = std::max(0, (row_end + kTileSize - 1) / kTileSize - first_tile_row);
    const size_t tile_count = size_t(tiles_x) * size_t(tiles_y);
    std::atomic<uint64_t> shadow_rays{0};
    size_t tiles_done = 0;
    std::mutex progress_mutex;
    const int workers = resolve_thread_count(threads);
    StallWatch watch(workers, stall_seconds > 0.0 ? stall_seconds : reference_stall_seconds(),
                     fmt::format("reference image ({} x {})", width, height));
    parallel_for(tile_count, workers, [&](size_t tile, int worker) {
        const int x0 = int(tile % size_t(tiles_x)) * kTileSize;
        const int tile_y = (first_tile_row + int(tile / size_t(tiles_x))) * kTileSize;
        const int y0 = std::max(tile_y, row_begin);
        const int x1 = std::min(x0 + kTileSize, width), y1 = std::min(tile_y + kTileSize, row_end);
        EmbreeShadowTracer tracer(shadow_scene, query);
        for (int y = y0; y < y1; ++y) {
            throw_if_interrupted();  // Ctrl-C: every worker stops within a row of pixels, nothing is kept
            for (int x = x0; x < x1; ++x) {
                watch.pixel_started(worker, x, y);
                pixel(x, y, tracer);
                watch.pixel_finished(worker);
            }
        }
        shadow_rays += tracer.rays();
        if (progress) {
            std::lock_guard lock(progress_mutex);
            progress(double(++tiles_done) / double(tile_count));
        }
    });
    return shadow_rays;
}

}  // namespace canopy
