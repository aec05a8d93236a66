// Every scenario file shipped under scenarios/ passes `hydrodda check`: a user's first run of
// any of them must not meet an input error.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "run_program.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> shipped_scenarios() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios"))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ShippedScenarios, AllPassCheck) {
  const auto files = shipped_scenarios();
  ASSERT_GE(files.size(), 20u);
  for (const fs::path& file : files) {
    const auto result = hydrodda::testing::run_program("check " + file.string());
    EXPECT_EQ(result.exit_code, 0) << file << ":\n" << result.output;
  }
}

}  // namespace
