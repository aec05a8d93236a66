// A run interrupted by Ctrl-C at a point it reports, and its resumption: the shared steps of the
// tests that a run stopped and resumed ends with the files of one never stopped.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <string>

#include "run_folder_compare.hpp"
#include "run_program.hpp"
#include "spawn_program.hpp"

namespace hydrodda::testing {

// `hydrodda run SCENARIO -o FOLDER --threads 1` held at its `check`-th stop check
// (cli/hold_points.hpp: the program waits there, no delay), then sent SIGINT: its exit code and
// what it printed; exit code −1 (and a test failure) when it ended before it was held.
inline ProgramResult interrupt_at_stop_check(const std::filesystem::path& scenario,
                                             const std::filesystem::path& folder, int check) {
  const std::filesystem::path log = folder.string() + ".log";
  RunningProgram program({"run", scenario.string(), "-o", folder.string(), "--threads", "1"}, log,
                         {"HYDRODDA_HOLD_AT_STOP_CHECK=" + std::to_string(check)});
  if (!program.wait_until_held()) {
    ADD_FAILURE() << "the run ended before its stop check " << check << ": " << program.output();
    return {-1, program.output()};
  }
  program.signal(SIGINT);
  if (!program.wait_for_exit()) {
    ADD_FAILURE() << "the run did not end after SIGINT: " << program.output();
    return {-1, program.output()};
  }
  return {program.exit_code(), program.output()};
}

// `run --resume FOLDER` ends with the files of `whole` (summary.json apart from its timings),
// and a second `run --resume` of the finished run is refused with exit code 2 and `refusal`.
inline void expect_resumes_to(const std::filesystem::path& folder, const std::filesystem::path& whole,
                              const std::string& refusal) {
  const auto resumed = run_program("run --resume " + folder.string() + " --threads 1");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  expect_same_results(whole, folder);
  const auto again = run_program("run --resume " + folder.string());
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_NE(again.output.find(refusal), std::string::npos) << again.output;
}

}  // namespace hydrodda::testing
