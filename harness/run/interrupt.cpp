#include "run/interrupt.hpp"

#include <atomic>
#include <csignal>
#include <unistd.h>

namespace canopy {

namespace {

std::atomic<int> received{0};

void on_signal(int signal) {
    int none = 0;
    if (!received.compare_exchange_strong(none, signal)) {  // the second signal: stop now
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    // At once, so Ctrl-C is seen to be taken (write() is safe in a signal handler; fmt is not).
    static constexpr char kSaid[] = "\ncanopy: stopping (a second Ctrl-C or SIGTERM ends canopy at once)\n";
    [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, kSaid, sizeof kSaid - 1);
}

}  // namespace

void install_interrupt_handler() {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
}

bool interrupt_requested() { return received.load() != 0; }

int interrupt_signal() { return received.load(); }

void throw_if_interrupted() {
    if (interrupt_requested()) throw Interrupted();
}

}  // namespace canopy
