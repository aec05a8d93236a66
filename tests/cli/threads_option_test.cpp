// --threads and HYDRODDA_THREADS: a bad value is bad input (exit 2) naming the option or the
// variable, before anything is run or written; a good one is what the run says it uses.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

const fs::path kScenario = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/loaded_block.toml";

fs::path fresh_folder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  return folder;
}

TEST(ThreadsOption, BadCountsAreBadInputNamingTheOption) {
  const fs::path folder = fresh_folder("hydrodda-threads-bad");
  for (const std::string& bad : {"0", "-2", "two", "1.5"}) {
    const auto result = run_program("run " + kScenario.string() + " -o " + folder.string() + " --threads=" + bad);
    EXPECT_EQ(result.exit_code, 2) << bad << ": " << result.output;
    EXPECT_NE(result.output.find("--threads"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(folder)) << bad;
  }
  const auto sweep = run_program("sweep " + kScenario.string() + " --set mechanics.steps=2 -o " + folder.string() +
                                 " --threads 0");
  EXPECT_EQ(sweep.exit_code, 2) << sweep.output;
  EXPECT_NE(sweep.output.find("--threads"), std::string::npos) << sweep.output;
  EXPECT_FALSE(fs::exists(folder));
}

TEST(ThreadsOption, ABadVariableIsBadInputNamingIt) {
  const fs::path folder = fresh_folder("hydrodda-threads-variable");
  for (const std::string& command : {"run " + kScenario.string() + " -o " + folder.string(),
                                     "sweep " + kScenario.string() + " --set mechanics.steps=2 -o " + folder.string()}) {
    const auto result = run_command("HYDRODDA_THREADS=0x2 " + std::string(HYDRODDA_BINARY) + " " + command);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("HYDRODDA_THREADS must be a whole number from 1 to 4096, got '0x2'"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(folder)) << command;
  }
}

// The option over the variable; each run says (with -v) how many it uses.
TEST(ThreadsOption, TheOptionComesBeforeTheVariable) {
  const fs::path folder = fresh_folder("hydrodda-threads-good");
  const auto chosen = run_command("HYDRODDA_THREADS=5 " + std::string(HYDRODDA_BINARY) + " -v run " +
                                  kScenario.string() + " -o " + folder.string() + " --threads 3");
  EXPECT_EQ(chosen.exit_code, 0) << chosen.output;
  EXPECT_NE(chosen.output.find("3 thread(s), as chosen"), std::string::npos) << chosen.output;
  fs::remove_all(folder);
  const auto variable = run_command("HYDRODDA_THREADS=5 " + std::string(HYDRODDA_BINARY) + " -v run " +
                                    kScenario.string() + " -o " + folder.string());
  EXPECT_EQ(variable.exit_code, 0) << variable.output;
  EXPECT_NE(variable.output.find("5 thread(s), as chosen"), std::string::npos) << variable.output;
  fs::remove_all(folder);
}

}  // namespace
