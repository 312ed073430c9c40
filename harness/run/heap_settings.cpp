#include "run/heap_settings.hpp"

#include <fmt/format.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace canopy {

namespace {

std::string& applied() {
    static std::string settings;
    return settings;
}

}  // namespace

std::string hold_heap_still() {
    std::string& settings = applied();
    if (!settings.empty()) return settings;
#if defined(__GLIBC__)
    // Trimming off: freed memory stays mapped, so reallocating it takes no page faults.
    constexpr int kTrimThreshold = 1 << 30;
    // Blocks up to 32 MiB (glibc's largest allowed threshold) come from the heap, not from an
    // mmap per allocation; a fixed value also stops glibc adjusting it as the process runs.
    constexpr int kMmapThreshold = 32 << 20;
    // Each time the heap grows, it grows by 64 MiB more than asked.
    constexpr int kTopPad = 64 << 20;
    const bool ok = mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1 && mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 &&
                    mallopt(M_TOP_PAD, kTopPad) == 1;
    settings = ok ? fmt::format("glibc trim_threshold={} mmap_threshold={} top_pad={}", kTrimThreshold, kMmapThreshold,
                                kTopPad)
                  : "allocator defaults (mallopt refused)";
#else
    settings = "allocator defaults (not glibc)";
#endif
    return settings;
}

std::string heap_settings() {
    const std::string& settings = applied();
    return settings.empty() ? "allocator defaults" : settings;
}

}  // namespace canopy
