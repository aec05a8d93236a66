#pragma once
// Points at which the program can be held until it is interrupted, so that a test signals a
// run at a known point of it (a log line, the N-th stop check) instead of after a delay, which
// a busy machine stretches. Chosen in the environment, read once:
//   HYDRODDA_HOLD_AFTER_LINE=TEXT   after the N-th log line containing TEXT, at any level (also
//                                   those that -q or the default leave out)
//   HYDRODDA_HOLD_AT_STOP_CHECK=N   at the N-th time the run asks whether to stop (before each
//                                   DDA step and each of its open–close passes, each coupling
//                                   iteration, each phase of a flow run)
//   HYDRODDA_HOLD_COUNT=N           the N of HYDRODDA_HOLD_AFTER_LINE (default 1)
// The thread that got there writes "held: ..." to stderr and waits until an interrupt (SIGINT,
// SIGTERM) has been taken, then goes on. Unset: nothing is held, and nothing costs.

#include <memory>

#include <spdlog/sinks/sink.h>

namespace hydrodda::cli {

// A log sink that holds after the chosen line; null when HYDRODDA_HOLD_AFTER_LINE is unset.
std::shared_ptr<spdlog::sinks::sink> make_line_hold_sink();

// Called at each stop check; holds at the chosen one.
void pass_stop_check();

}  // namespace hydrodda::cli
