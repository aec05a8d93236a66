#include "sweep/child_processes.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>
#include <thread>


extern char** environ;

namespace hydrodda::sweep {

namespace {

// The launcher's variables stay with the sweep's rank: a case is a program of its own, not
// another process of the MPI job.
bool is_mpi_launch_variable(const char* entry) {
  for (const char* prefix : {"OMPI_", "PMIX_", "PMI_"})
    if (std::strncmp(entry, prefix, std::strlen(prefix)) == 0) return true;
  return false;
}

std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (!is_mpi_launch_variable(*e)) env.emplace_back(*e);
  if (!std::getenv("OMP_NUM_THREADS")) env.emplace_back("OMP_NUM_THREADS=1");
  return env;
}

std::vector<char*> to_argv(std::vector<std::string>& strings) {
  std::vector<char*> argv;
  for (std::string& s : strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  return argv;
}

pid_t start_child(const ChildCommand& command, std::vector<std::string> env) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, command.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<std::string> arguments = command.arguments;
  std::vector<char*> argv = to_argv(arguments);
  std::vector<char*> envp = to_argv(env);
  pid_t pid = 0;
  // A case starts with SIGINT and SIGTERM blocked, as the sweep has them: one forwarded while
  // the case's program is still loading waits, pending, for its signal thread, so the case ends
  // as interrupted instead of being killed before it can say so.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t interrupts;
  sigemptyset(&interrupts);
  sigaddset(&interrupts, SIGINT);
  sigaddset(&interrupts, SIGTERM);
  posix_spawnattr_setsigmask(&attributes, &interrupts);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  const int error = ::posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), envp.data());
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0)
    throw std::runtime_error(fmt::format("cannot start {}: {}", command.arguments[0], std::strerror(error)));
  return pid;
}

int exit_code_of(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace

int start_child_process(const ChildCommand& command) { return start_child(command, child_environment()); }

std::optional<int> poll_child_process(int pid) {
  int status = 0;
  const pid_t ended = ::waitpid(pid, &status, WNOHANG);
  if (ended == pid) return exit_code_of(status);
  if (ended < 0 && errno != EINTR)
    throw std::runtime_error(fmt::format("waiting for a case's process failed: {}", std::strerror(errno)));
  return std::nullopt;
}

std::vector<std::size_t> run_child_processes(const std::vector<ChildCommand>& commands, int jobs,
                                             const std::function<void(std::size_t, int)>& on_finish,
                                             const std::function<bool()>& stop_requested) {
  const std::vector<std::string> env = child_environment();
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0;
  bool forwarded = false;
  // Polled rather than blocking in waitpid, so that an interrupt is seen within 50 ms.
  while (next < commands.size() || !running.empty()) {
    if (stop_requested() && !forwarded) {
      for (const auto& [pid, index] : running) ::kill(pid, SIGINT);
      forwarded = true;
    }
    while (!stop_requested() && next < commands.size() && static_cast<int>(running.size()) < jobs) {
      try {
        running[start_child(commands[next], env)] = next;
      } catch (const std::runtime_error&) {
        // No child is left behind: the running ones are stopped and waited for.
        for (const auto& [pid, index] : running) ::kill(pid, SIGINT);
        for (const auto& [pid, index] : running) {
          int status = 0;
          ::waitpid(pid, &status, 0);
          on_finish(index, exit_code_of(status));
        }
        throw;
      }
      ++next;
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid > 0 && running.count(pid)) {
      const std::size_t index = running[pid];
      running.erase(pid);
      on_finish(index, exit_code_of(status));
    } else if (pid == 0 || (pid < 0 && errno == EINTR)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    } else if (pid < 0) {
      throw std::runtime_error(fmt::format("waiting for the child processes failed: {}", std::strerror(errno)));
    }
  }
  std::vector<std::size_t> never_started;
  for (std::size_t i = next; i < commands.size(); ++i) never_started.push_back(i);
  return never_started;
}

}  // namespace hydrodda::sweep
