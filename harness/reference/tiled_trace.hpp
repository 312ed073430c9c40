// The loop both reference images share: the image in 16x16 tiles spread over threads, each tile
// with its own shadow-ray tracer (packets are per thread), progress reported once per finished
// tile, serialised and monotonic.
#pragma once

#include "reference/reference_settings.hpp"
#include "reference/shadow_packet.hpp"

#include <cstdint>
#include <functional>

namespace canopy {

// Calls `pixel(x, y, tracer)` once for every pixel of a width x height image in the band `rows`
// (RowBand: every row by default), on `threads` threads (0: every hardware thread). Returns the shadow rays the tracers traced. A StallWatch
// (stall_watch.hpp) ends the process when no pixel finishes for `stall_seconds` (0:
// reference_stall_seconds()). Once an interrupt is requested (run/interrupt.hpp) every worker
// stops within a row of its tile and Interrupted is thrown: no half image is returned.
uint64_t trace_tiles(int width, int height, int threads, RTCScene shadow_scene, ShadowQuery query,
                     const std::function<void(double fraction_done)>& progress,
                     const std::function<void(int x, int y, EmbreeShadowTracer& tracer)>& pixel,
                     double stall_seconds = 0.0, RowBand rows = {});

}  // namespace canopy
