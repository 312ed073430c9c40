// A watchdog for the reference's tiles: Embree cannot be interrupted inside a ray query, so a
// query that never returns (Embree 3.13 was seen to loop forever in rtcOccluded16, shadow_packet.hpp)
// would hang a run for good. While armed, a monitor thread watches the pixels finished; when none
// finishes for `limit` seconds it prints the pixels each worker was tracing and what to do, and
// ends the process with exit code 1 (a run resumes from its last recorded group). Cheap: workers
// only store two integers per pixel.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace canopy {

// The stall limit: $CANOPY_REFERENCE_STALL_SECONDS when set (a positive number), else 300 s (a
// pixel of the committed experiments takes at most milliseconds).
double reference_stall_seconds();

class StallWatch {
public:
    // `what` names the image in the message ("reference grass-field 320x180").
    StallWatch(int workers, double limit_seconds, std::string what);
    ~StallWatch();  // stops the monitor
    StallWatch(const StallWatch&) = delete;
    StallWatch& operator=(const StallWatch&) = delete;

    void pixel_started(int worker, int x, int y);
    void pixel_finished(int worker);

private:
    void monitor();
    [[noreturn]] void stalled(double seconds) const;

    struct Slot {
        std::atomic<int64_t> pixel{-1};  // y << 32 | x, or -1 when idle
    };
    std::vector<std::unique_ptr<Slot>> slots_;
    std::atomic<uint64_t> finished_{0};
    double limit_;
    std::string what_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace canopy
