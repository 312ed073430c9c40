// Ctrl-C during a run: finish nothing more, keep every finished case, mark the run interrupted.
#pragma once

namespace canopy {

void install_interrupt_handler();  // SIGINT and SIGTERM set the flag; a second SIGINT kills
bool interrupt_requested();

}  // namespace canopy
