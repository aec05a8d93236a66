#pragma once
// SIGINT and SIGTERM ask a run to stop after the current step or iteration, so that the run
// folder is left consistent rather than cut mid-write.

namespace hydrodda::cli {

void install_interrupt_handlers();
bool interrupt_requested();

}  // namespace hydrodda::cli
