#pragma once
// Starts the real hydrodda program in the background, for tests that signal it while it runs.
//
// A test signals the program on an event it can see, never after a delay (which a busy machine
// stretches): a line in its output, a file it writes, or a point it is held at until the signal
// comes (HYDRODDA_HOLD_AFTER_LINE, HYDRODDA_HOLD_AT_STOP_CHECK: src/cli/hold_points.hpp; the
// held program says "held: ..."). The time limits here only guard against a hang: a test fails
// when one runs out.

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace hydrodda::testing {

// Long enough for any run these tests make on a loaded machine; reached only by a hang.
inline constexpr std::chrono::seconds kHangGuard{600};

// The child's pid; with own_process_group a signal to the test's group does not reach it.
// Its stdout and stderr go to `log` (to /dev/null when empty); `environment` ("NAME=value")
// is added to the test's.
inline pid_t start_program(const std::vector<std::string>& arguments, const std::filesystem::path& log = {},
                           const std::vector<std::string>& environment = {}, bool own_process_group = false) {
  std::vector<std::string> strings{HYDRODDA_BINARY};
  strings.insert(strings.end(), arguments.begin(), arguments.end());
  std::vector<std::string> env(environment);
  for (char** e = environ; *e; ++e) env.emplace_back(*e);  // the first of a name counts: the test's additions
  std::vector<char*> argv, envp;
  for (std::string& s : strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  for (std::string& s : env) envp.push_back(s.data());
  envp.push_back(nullptr);
  const std::string output = log.empty() ? "/dev/null" : log.string();
  if (!log.empty()) std::ofstream(log, std::ios::trunc).close();  // emptied before the test can read it
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  if (own_process_group) ::setpgid(0, 0);
  const int out = ::open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(out, STDOUT_FILENO);
  ::dup2(out, STDERR_FILENO);
  ::execve(HYDRODDA_BINARY, argv.data(), envp.data());
  ::_exit(127);
}

inline pid_t start_program_silently(const std::vector<std::string>& arguments, bool own_process_group = false) {
  return start_program(arguments, {}, {}, own_process_group);
}

inline std::string read_whole_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Waits until `file` holds `text`; false when `still_going` says no first, or the guard runs out.
inline bool wait_for_text(const std::filesystem::path& file, const std::string& text,
                          const std::function<bool()>& still_going, std::chrono::seconds guard = kHangGuard) {
  const auto deadline = std::chrono::steady_clock::now() + guard;
  while (std::chrono::steady_clock::now() < deadline) {
    if (read_whole_file(file).find(text) != std::string::npos) return true;
    if (!still_going()) return read_whole_file(file).find(text) != std::string::npos;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

// A program started by start_program, with its output in a file; killed (SIGKILL) when the
// test leaves it running.
class RunningProgram {
 public:
  RunningProgram(const std::vector<std::string>& arguments, const std::filesystem::path& log,
                 const std::vector<std::string>& environment = {}, bool own_process_group = false)
      : log_(log), pid_(start_program(arguments, log, environment, own_process_group)) {}
  ~RunningProgram() {
    if (!ended_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status_, 0);
    }
  }
  RunningProgram(const RunningProgram&) = delete;
  RunningProgram& operator=(const RunningProgram&) = delete;

  pid_t pid() const { return pid_; }
  void signal(int signal) const { ::kill(pid_, signal); }
  std::string output() const { return read_whole_file(log_); }

  // Whether it still runs (reaping it when it has ended).
  bool running() {
    if (!ended_ && ::waitpid(pid_, &status_, WNOHANG) == pid_) ended_ = true;
    return !ended_;
  }
  // Waits until its output holds `text`; false when it ended first.
  bool wait_for_output(const std::string& text) {
    return wait_for_text(log_, text, [this] { return running(); });
  }
  // Waits until `done(its output so far)`; false when it ended first.
  bool wait_for(const std::function<bool(const std::string&)>& done) {
    const auto deadline = std::chrono::steady_clock::now() + kHangGuard;
    while (std::chrono::steady_clock::now() < deadline) {
      if (done(output())) return true;
      if (!running()) return done(output());
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }
  // Waits until its output is no longer `size` characters long; false when it ended first.
  bool wait_for_output_change(std::size_t size) {
    return wait_for([size](const std::string& output) { return output.size() != size; }) && running();
  }
  // Waits until it has been held (cli/hold_points.hpp); false when it ended first.
  bool wait_until_held() { return wait_for_output("held: "); }
  // Waits for it to end; false (and killed) when the guard runs out.
  bool wait_for_exit(std::chrono::seconds guard = kHangGuard) {
    const auto deadline = std::chrono::steady_clock::now() + guard;
    while (running() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!running()) return true;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status_, 0);
    ended_ = true;
    return false;
  }
  // Its exit code once it has ended by exiting, else -1 (128 + the signal when one killed it).
  int exit_code() const {
    if (!ended_) return -1;
    if (WIFEXITED(status_)) return WEXITSTATUS(status_);
    return WIFSIGNALED(status_) ? 128 + WTERMSIG(status_) : -1;
  }

 private:
  std::filesystem::path log_;
  pid_t pid_;
  int status_ = 0;
  bool ended_ = false;
};

}  // namespace hydrodda::testing
