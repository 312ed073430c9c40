#include "run/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace canopy {

namespace {

std::atomic<int> received{0};

void on_signal(int signal) {
    int none = 0;
    if (!received.compare_exchange_strong(none, signal)) {  // the second signal: stop now
        std::signal(signal, SIG_DFL);
        std::raise(signal);
    }
}

}  // namespace

void install_interrupt_handler() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}

bool interrupt_requested() { return received.load() != 0; }

int interrupt_signal() { return received.load(); }

}  // namespace canopy
