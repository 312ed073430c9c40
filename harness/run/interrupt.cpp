#include "run/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace canopy {

namespace {

std::atomic<bool> requested{false};

void on_signal(int signal) {
    if (requested.exchange(true) && signal == SIGINT) {
        std::signal(SIGINT, SIG_DFL);
        std::raise(SIGINT);
    }
}

}  // namespace

void install_interrupt_handler() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}

bool interrupt_requested() { return requested.load(); }

}  // namespace canopy
