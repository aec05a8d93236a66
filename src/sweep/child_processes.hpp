#pragma once
// Running copies of a program side by side, a few at a time, as a parameter sweep does.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hydrodda::sweep {

struct ChildCommand {
  std::vector<std::string> arguments;  // arguments[0] is the program
  std::filesystem::path log;           // receives the child's stdout and stderr
};

// Runs the commands with at most `jobs` at a time, in order, calling `on_finish(index, exit
// code)` as each ends (128 + the signal for one killed by a signal). Children get stdin from
// /dev/null and OMP_NUM_THREADS=1 unless it is set, so that `jobs` processes share the cores
// rather than each filling them. Once `stop_requested()` (the program had SIGINT or SIGTERM), no further
// command is started and the running children are sent SIGINT; returns when all have ended,
// with the indices of the commands never started. Throws std::runtime_error if a child cannot
// be started.
std::vector<std::size_t> run_child_processes(const std::vector<ChildCommand>& commands, int jobs,
                                             const std::function<void(std::size_t, int)>& on_finish,
                                             const std::function<bool()>& stop_requested);

// One child started as run_child_processes starts them (a sweep's rank under MPI runs its
// cases one at a time with it); throws std::runtime_error if it cannot be started.
int start_child_process(const ChildCommand& command);
// The child's exit code (128 + the signal for one killed by a signal) once it has ended, or
// nothing while it runs; throws std::runtime_error if it cannot be waited for.
std::optional<int> poll_child_process(int pid);

}  // namespace hydrodda::sweep
