// A mechanics-only run through the real program: exit code, run folder, summary values.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

// A block pushed sideways against its joint's friction (tests/cli/scenarios/pushed_block.toml):
// friction holds it up to F* = tan φ ρ g A = 4324 N/m (the force balance, exact for a block on a
// frictional plane). At F*/2 it stays (exit 0, status "ok"). At 2 F* no equilibrium exists:
// the static analysis slides it on, farther than its own 1 m, and the run ends with status
// "no equilibrium", exit 1, naming the load and the block at its centroid as summary.json has it.
TEST(MechanicsRun, ABlockPushedPastItsFrictionHasNoEquilibrium) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/pushed_block.toml";
  std::ifstream in(scenario);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const double f_star = std::tan(10.0 * M_PI / 180.0) * 2500.0 * 9.81;
  for (const double ratio : {0.5, 2.0}) {
    std::string edited = text;
    const std::string held = "force = [2162.0, 0.0]";
    ASSERT_NE(edited.find(held), std::string::npos);
    char force[64];
    std::snprintf(force, sizeof force, "force = [%.1f, 0.0]", ratio * f_star);
    edited.replace(edited.find(held), held.size(), force);
    const fs::path file = fs::temp_directory_path() / "hydrodda-pushed-block.toml";
    std::ofstream(file) << edited;
    const fs::path out = fs::temp_directory_path() / "hydrodda-pushed-block";
    fs::remove_all(out);
    const auto result = run_program("-q run " + file.string() + " -o " + out.string() + " --threads 1");
    const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
    const auto& block = summary["blocks"][1];
    const double moved = std::hypot(block["displacement"][0].get<double>(), block["displacement"][1].get<double>());
    if (ratio < 1.0) {
      EXPECT_EQ(result.exit_code, 0) << result.output;
      EXPECT_EQ(summary["status"], "ok");
      EXPECT_LT(moved, 1e-3) << "friction holds the block";
    } else {
      EXPECT_EQ(result.exit_code, 1) << result.output;
      EXPECT_EQ(summary["status"], "no equilibrium");
      EXPECT_EQ(summary["converged"], false);
      EXPECT_GT(moved, 1.0);
      const std::string message = summary["message"];
      char named[128];
      std::snprintf(named, sizeof named, "no mechanical equilibrium under mechanics.load at (1.5, 1.5) force = [%.4g, 0] N/m: 1 block(s)",
                    std::round(ratio * f_star * 10.0) / 10.0);
      EXPECT_NE(message.find(named), std::string::npos) << message;
      std::snprintf(named, sizeof named, "block 1 at (%.4g, %.4g) (moved %.3g m, size 1 m)",
                    block["centroid"][0].get<double>(), block["centroid"][1].get<double>(), moved);
      EXPECT_NE(message.find(named), std::string::npos) << message;
      EXPECT_NE(message.find("(summary.json, history.csv and the figures are of DDA step " +
                             std::to_string(summary["iterations"].get<int>()) + ")"),
                std::string::npos) << message;
      EXPECT_EQ(message.find("time step fell below"), std::string::npos) << message;
    }
    fs::remove_all(out);
    fs::remove(file);
  }
}

// A static run's `converged` says its blocks are at rest at its end (run/mechanics_rest.hpp):
// the pushed block (held by friction at F*/2) at a time step of 1e-4 s, where a static step's
// inertia 2M/Δt² = 5e11 N/m is as stiff as its contacts' springs and each step closes only part
// of the way to equilibrium. Cut short at 2 steps the block still moves (6e-8 m a step against
// the 1e-9 m at rest, its unbalanced force half the forces on it): exit 0, status "ok",
// converged false, and the message says by how much, which block and what to raise. Given 300
// steps it is at rest: converged.
TEST(MechanicsRun, AStaticRunCutShortOfRestIsNotConverged) {
  const fs::path original = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/pushed_block.toml";
  for (const int steps : {2, 300}) {
    const fs::path file = hydrodda::testing::edited_scenario(
        original, "hydrodda-static-rest-" + std::to_string(steps),
        {{"time_step = 1.0", "time_step = 1.0e-4"}, {"steps = 300", "steps = " + std::to_string(steps)}});
    const fs::path out = fs::temp_directory_path() / ("hydrodda-static-rest-" + std::to_string(steps));
    fs::remove_all(out);
    const auto result = run_program("run " + file.string() + " -o " + out.string() + " --threads 1");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    const auto summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
    EXPECT_EQ(summary["status"], "ok");
    EXPECT_EQ(summary["iterations"], steps);
    if (steps == 2) {
      EXPECT_EQ(summary["converged"], false);
      const std::string message = summary["message"];
      EXPECT_NE(message.find("the blocks were not at rest at the end: the last step (step 2) still moved a vertex by"),
                std::string::npos) << message;
      EXPECT_NE(message.find("block 1 at (1.5, 1.5)"), std::string::npos) << message;
      EXPECT_NE(message.find("raise mechanics.steps"), std::string::npos) << message;
      EXPECT_NE(result.output.find("not converged; results in"), std::string::npos) << result.output;
    } else {
      EXPECT_EQ(summary["converged"], true) << summary["message"];
    }
    fs::remove_all(out);
    fs::remove(file);
  }
}

}  // namespace
