#pragma once
// Runs the real hydrodda program and captures what it prints, for command-line tests.

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace hydrodda::testing {

struct ProgramResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline ProgramResult run_program(const std::string& arguments) {
  const std::string command = std::string(HYDRODDA_BINARY) + " " + arguments + " 2>&1";
  ProgramResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace hydrodda::testing
