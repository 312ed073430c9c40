#include "reference/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace canopy {

int resolve_thread_count(int threads) {
    if (threads > 0) return threads;
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

void parallel_for(size_t count, int threads, const std::function<void(size_t, int)>& body) {
    const int workers = int(std::min<size_t>(size_t(resolve_thread_count(threads)), std::max<size_t>(count, 1)));
    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first_error;
    std::mutex error_mutex;
    const auto work = [&](int worker) {
        for (size_t index = next++; index < count && !failed; index = next++) {
            try {
                body(index, worker);
            } catch (...) {
                std::lock_guard lock(error_mutex);
                if (!first_error) first_error = std::current_exception();
                failed = true;
            }
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(size_t(workers - 1));
    for (int worker = 1; worker < workers; ++worker) pool.emplace_back(work, worker);
    work(0);
    for (std::thread& thread : pool) thread.join();
    if (first_error) std::rethrow_exception(first_error);
}

}  // namespace canopy
