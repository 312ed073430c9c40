// How the C heap behaves while canopy measures. glibc gives freed memory at the top of the heap
// back to the kernel (trimming) and serves large blocks with fresh mmaps, so a driver that
// frees and reallocates its working memory every frame (lavapipe's binned scenes do) takes page
// faults inside the timed passes, and how many depends on what the rest of the process happened
// to allocate before. canopy keeps freed memory in the process instead, so a pass's time does
// not depend on the heap's history.
#pragma once

#include <string>

namespace canopy {

// Applies the settings once per process (later calls do nothing) and says what they are.
// Call it before any device is created.
std::string hold_heap_still();

// What hold_heap_still() set in this process, or "allocator defaults" when it was not called
// (or the C library is not glibc). Recorded in every run's environment.
std::string heap_settings();

}  // namespace canopy
