// Ctrl-C or SIGTERM during a run: finish nothing more, keep every finished case, mark the run
// interrupted (it can be resumed). A second signal ends the process at once.
#pragma once

namespace canopy {

void install_interrupt_handler();  // SIGINT and SIGTERM set the flag; a second one kills
bool interrupt_requested();
int interrupt_signal();            // the signal that asked to stop (SIGINT, SIGTERM), 0 if none

}  // namespace canopy
