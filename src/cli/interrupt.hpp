#pragma once
// SIGINT and SIGTERM ask a run to stop after the current step or iteration, so that the run
// folder is left consistent rather than cut mid-write.
//
// They are blocked in every thread and taken by one thread of their own with sigwait, so no
// library can lose one by installing handlers of its own (METIS, inside CHOLMOD, swaps in
// gk_sigtrap while it orders a matrix and puts back the program's with SA_RESETHAND).

#include <filesystem>

namespace hydrodda::cli {

// First thing in main: from then on an interrupt waits, pending, for the signal thread instead
// of ending the process by the default action (before main, while the dynamic loader maps the
// program's libraries, nothing of ours can take it; a sweep starts its cases with both blocked).
void block_interrupt_signals();
// Call before any other thread starts: threads inherit the blocked set.
void start_interrupt_thread();
bool interrupt_requested();
// Returns once an interrupt has been taken and has not ended the process (at once if one has).
void wait_for_interrupt();

// While a stage runs that cannot stop and leaves nothing to keep (building the model, which
// Gmsh may spend minutes on), an interrupt ends the process at once with exit code 1, removing
// `folder` if it is empty. Given false, a later interrupt only asks the run to stop.
void set_exit_on_interrupt(bool on, const std::filesystem::path& folder = {});

}  // namespace hydrodda::cli
