// Ctrl-C or SIGTERM during a run: finish nothing more, keep every finished case, mark the run
// interrupted (it can be resumed). A second signal ends the process at once.
#pragma once

#include <stdexcept>

namespace canopy {

void install_interrupt_handler();  // SIGINT and SIGTERM set the flag (saying so on stderr); a second one kills
bool interrupt_requested();
int interrupt_signal();            // the signal that asked to stop (SIGINT, SIGTERM), 0 if none

// Thrown by long work that cannot end early with a usable result (a reference ray-trace, whose
// half image must not be cached) when an interrupt was requested: what it computed is dropped.
class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("interrupted") {}
};
void throw_if_interrupted();  // throws Interrupted once interrupt_requested()

}  // namespace canopy
