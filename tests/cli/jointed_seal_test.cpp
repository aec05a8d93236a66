// The shipped example of a jointed seal (scenarios/examples/jointed_seal.toml): joint sets,
// in-situ stress and rollers through the program, as a user first meets them.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "run_program.hpp"

namespace {

using hydrodda::testing::run_program;

std::string scenario_path() { return std::string(HYDRODDA_SOURCE_DIR) + "/scenarios/examples/jointed_seal.toml"; }

// The traces and blocks are the seeds' on every machine: the counts `check` prints are fixed.
TEST(JointedSeal, CheckCountsTheTracesAndBlocks) {
  const auto result = run_program("check " + scenario_path());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("18 traces (14 from joint set 1, 4 from joint set 2), 24 blocks (2 slivers merged)"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("2 blocks smaller than"), std::string::npos) << result.output;
}

// The run converges, and the seal stays in the stress it started in: every block's stress
// within 2% of the in-situ value at its centroid (the 1 MPa overpressure changes it by less),
// and no block moves by more than 0.1 mm.
TEST(JointedSeal, RunsAndKeepsItsInSituStress) {
  const auto s = hydrodda::testing::run_scenario_and_read("scenarios/examples/jointed_seal.toml");
  EXPECT_TRUE(s["converged"].get<bool>());
  ASSERT_EQ(s["blocks"].size(), 24u);
  for (const auto& b : s["blocks"]) {
    const double y = b["centroid"][1];
    const double syy = -2.0e7 - 23544.0 * (6.0 - y), sxx = -1.4e7 - 16480.8 * (6.0 - y);
    EXPECT_NEAR(double(b["stress"][1]), syy, 0.02 * std::abs(syy)) << "block " << b["id"];
    EXPECT_NEAR(double(b["stress"][0]), sxx, 0.02 * std::abs(sxx)) << "block " << b["id"];
    EXPECT_LE(std::hypot(double(b["displacement"][0]), double(b["displacement"][1])), 1e-4) << "block " << b["id"];
  }
}

}  // namespace
