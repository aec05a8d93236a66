#pragma once
// Starts the real hydrodda program in the background, its output thrown away, for tests that
// signal it while it runs.

#include <fcntl.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace hydrodda::testing {

// The child's pid; with own_process_group a signal to the test's group does not reach it.
inline pid_t start_program_silently(const std::vector<std::string>& arguments, bool own_process_group = false) {
  std::vector<std::string> strings{HYDRODDA_BINARY};
  strings.insert(strings.end(), arguments.begin(), arguments.end());
  const pid_t pid = ::fork();
  if (pid != 0) return pid;
  if (own_process_group) ::setpgid(0, 0);
  const int null = ::open("/dev/null", O_WRONLY);
  ::dup2(null, STDOUT_FILENO);
  ::dup2(null, STDERR_FILENO);
  std::vector<char*> argv;
  for (std::string& s : strings) argv.push_back(s.data());
  argv.push_back(nullptr);
  ::execv(HYDRODDA_BINARY, argv.data());
  ::_exit(127);
}

}  // namespace hydrodda::testing
