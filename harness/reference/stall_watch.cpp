#include "reference/stall_watch.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>

namespace canopy {

double reference_stall_seconds() {
    if (const char* value = std::getenv("CANOPY_REFERENCE_STALL_SECONDS"); value && *value) {
        char* end = nullptr;
        const double seconds = std::strtod(value, &end);
        if (end && *end == '\0' && seconds > 0.0) return seconds;
    }
    return 300.0;
}

StallWatch::StallWatch(int workers, double limit_seconds, std::string what)
    : limit_(limit_seconds), what_(std::move(what)) {
    for (int w = 0; w < workers; ++w) slots_.push_back(std::make_unique<Slot>());
    thread_ = std::thread([this] { monitor(); });
}

StallWatch::~StallWatch() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void StallWatch::pixel_started(int worker, int x, int y) {
    slots_[size_t(worker)]->pixel.store((int64_t(y) << 32) | int64_t(uint32_t(x)), std::memory_order_relaxed);
}

void StallWatch::pixel_finished(int worker) {
    slots_[size_t(worker)]->pixel.store(-1, std::memory_order_relaxed);
    finished_.fetch_add(1, std::memory_order_relaxed);
}

void StallWatch::monitor() {
    using Clock = std::chrono::steady_clock;
    uint64_t seen = finished_.load();
    Clock::time_point since = Clock::now();
    std::unique_lock lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, std::chrono::milliseconds(200));
        if (stop_) break;
        const uint64_t now_finished = finished_.load(std::memory_order_relaxed);
        const Clock::time_point now = Clock::now();
        if (now_finished != seen) {
            seen = now_finished;
            since = now;
            continue;
        }
        const double idle = std::chrono::duration<double>(now - since).count();
        if (idle >= limit_) stalled(idle);
    }
}

void StallWatch::stalled(double seconds) const {
    std::string pixels;
    for (size_t w = 0; w < slots_.size(); ++w) {
        const int64_t p = slots_[w]->pixel.load(std::memory_order_relaxed);
        if (p >= 0) pixels += fmt::format("{}({}, {})", pixels.empty() ? "" : ", ", int(p & 0xffffffff), int(p >> 32));
    }
    std::fprintf(stderr,
                 "canopy: the %s stalled: no pixel finished in %.0f s (pixels being traced: %s); Embree did not "
                 "return from a ray query and cannot be interrupted, so canopy stops here (exit code 1)\n"
                 "  hint: run the same command again: it resumes from the last recorded group, and the reference's "
                 "BVH is built anew; CANOPY_REFERENCE_STALL_SECONDS sets this limit (now %.0f s)\n",
                 what_.c_str(), seconds, pixels.empty() ? "none" : pixels.c_str(), limit_);
    std::fflush(stderr);
    std::_Exit(1);
}

}  // namespace canopy
