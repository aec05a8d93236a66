// The same coupled scenario run twice gives the same run folder byte for byte: summary.json
// (apart from `timings`, wall-clock seconds), history.csv, every .vtu and .pvd and the scenario
// copy. Nothing that depends on timing, addresses or hash-table order reaches a result.

#include <gtest/gtest.h>

#include <filesystem>

#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;

namespace {

TEST(Determinism, ACoupledRunTwiceGivesTheSameFilesByteForByte) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper/six_block_ud_bt.toml";
  const fs::path first = fs::temp_directory_path() / "hydrodda-determinism-1";
  const fs::path second = fs::temp_directory_path() / "hydrodda-determinism-2";
  fs::remove_all(first);
  fs::remove_all(second);
  for (const fs::path& out : {first, second}) {
    const auto result = hydrodda::testing::run_program("run " + scenario.string() + " -o " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
  }
  int vtu_files = 0;
  for (const auto& entry : fs::directory_iterator(first)) vtu_files += entry.path().extension() == ".vtu";
  EXPECT_GE(vtu_files, 4);  // fluid and blocks, at least two iterations
  hydrodda::testing::expect_same_results(first, second);
  fs::remove_all(first);
  fs::remove_all(second);
}

}  // namespace
