// A mechanics-only run through the real program: exit code, run folder, summary values.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

TEST(MechanicsRun, LoadedBlockWritesTheRunFolder) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/loaded_block.toml";
  const fs::path out = fs::temp_directory_path() / "hydrodda-loaded-block";
  fs::remove_all(out);
  const auto result = run_program("run " + scenario.string() + " -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  ASSERT_TRUE(fs::exists(out / "history.csv"));
  ASSERT_TRUE(fs::exists(out / "measure.csv"));

  const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["converged"], true);
  EXPECT_EQ(summary["iterations"], 200);
  ASSERT_EQ(summary["blocks"].size(), 2u);
  // σyy of the top block = −1e6 − ρ g × 0.5 (the file states it); 1% as for the stack test.
  const double expected = -1.0e6 - 2500.0 * 9.81 * 0.5;
  const double syy = summary["blocks"][1]["stress"][1];
  EXPECT_NEAR(syy, expected, 0.01 * std::abs(expected));
  // The fixed base does not move.
  EXPECT_EQ(summary["blocks"][0]["displacement"][0], 0.0);
  EXPECT_EQ(summary["blocks"][0]["displacement"][1], 0.0);
  EXPECT_TRUE(summary["measure"].contains("top"));

  // measure.csv: a header and one row per step for the one measured point.
  std::ifstream csv(out / "measure.csv");
  std::string line;
  int rows = -1;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 200);
  fs::remove_all(out);
}

}  // namespace
