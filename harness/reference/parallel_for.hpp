// A minimal dynamic work queue over std::thread. canopy_core does not link TBB (Embree only
// uses it internally), and tiles of a reference image are all this needs: each worker takes
// the next unclaimed index until none is left.
#pragma once

#include <cstddef>
#include <functional>

namespace canopy {

// 0 = std::thread::hardware_concurrency().
int resolve_thread_count(int threads);

// Runs body(index, worker) for every index in [0, count), on `threads` workers (worker in
// [0, threads)). The first exception thrown by a body stops the remaining work and is rethrown.
void parallel_for(size_t count, int threads, const std::function<void(size_t index, int worker)>& body);

}  // namespace canopy
