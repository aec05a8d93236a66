// The shipped example of a jointed seal (scenarios/examples/jointed_seal.toml): joint sets,
// in-situ stress and rollers through the program, as a user first meets them.

#include <gtest/gtest.h>

#include <algorithm>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "run_program.hpp"

namespace {

using hydrodda::testing::read_csv;
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
// within 2% of the in-situ value at its centroid, and no block moves by more than 0.1 mm. The
// blocks carry the effective stress (Biot α = 1): σ'yy = σyy + p = −20 MPa + G (6 m − y),
// G = ρ_w g (1 + Δh/L) − ρ_r g = 9,810 (1 + 100/6) − 23,544 = 149,766 Pa/m for the upward
// seepage from 106 m of head at the base to 6 m at the top, and σ'xx = 0.7 σ'yy.
TEST(JointedSeal, RunsAndKeepsItsInSituStress) {
  const auto s = hydrodda::testing::run_scenario_and_read("scenarios/examples/jointed_seal.toml");
  EXPECT_TRUE(s["converged"].get<bool>());
  ASSERT_EQ(s["blocks"].size(), 24u);
  for (const auto& b : s["blocks"]) {
    const double y = b["centroid"][1];
    const double syy = -2.0e7 + 149766.0 * (6.0 - y), sxx = 0.7 * syy;
    EXPECT_NEAR(double(b["stress"][1]), syy, 0.02 * std::abs(syy)) << "block " << b["id"];
    EXPECT_NEAR(double(b["stress"][0]), sxx, 0.02 * std::abs(sxx)) << "block " << b["id"];
    EXPECT_LE(std::hypot(double(b["displacement"][0]), double(b["displacement"][1])), 1e-4) << "block " << b["id"];
  }
}

// Blocks that rest on the domain's edge reach past the fixed fluid mesh by round-off only
// (2.2e-13 m here, where the DDA holds positions to its penetration tolerance, 3e-6 m): that is
// no excursion, so the run does not warn of one, while summary.json still reports the distance.
TEST(JointedSeal, RoundOffPastTheMeshEdgeIsNoWarning) {
  const std::string out = (std::filesystem::temp_directory_path() / "hydrodda-jointed-seal-edge").string();
  std::filesystem::remove_all(out);
  const auto result = run_program("run " + scenario_path() + " -o " + out);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("reach outside the fluid mesh"), std::string::npos) << result.output;
  std::ifstream in(std::filesystem::path(out) / "summary.json");
  ASSERT_TRUE(in);
  const nlohmann::json summary = nlohmann::json::parse(in);
  EXPECT_LT(double(summary["outside_mesh"]["largest_distance"]), 1e-9);
  std::filesystem::remove_all(out);
}

// docs/tutorial.md's sweep, as its table states it: at 1500 m and 2000 m of overpressure head
// (base heads 1506 m and 2006 m over the top's 6 m) the joints
// listed there open over some of their length at the last iteration (open_share > 0; the ids as
// fractures.csv writes them), the
// cases converge, and K_eff = Q_top / (20 m × (H_base − 6 m) / 6 m) stays 6.73e-11 m/s (to 0.5%).
TEST(JointedSeal, TutorialSweepOpensTheJointsItLists) {
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / ("hydrodda-tutorial-sweep-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto result = run_program("-q sweep " + scenario_path() + " --set 'flow.boundary[0].head=1506,2006'" +
                                  " --column flow.boundaries.top -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto sweep = read_csv(out / "sweep.csv");
  ASSERT_EQ(sweep.size(), 3u);
  const std::vector<std::set<std::string>> listed{{"14"}, {"14", "15"}};
  const double heads[] = {1506.0, 2006.0};
  for (int c = 0; c < 2; ++c) {
    EXPECT_EQ(sweep[c + 1][3], "true") << "case " << c;
    const double k_eff = std::stod(sweep[c + 1][5]) / (20.0 * (heads[c] - 6.0) / 6.0);
    EXPECT_NEAR(k_eff, 6.73e-11, 0.005 * 6.73e-11) << "case " << c;
    const auto rows = read_csv(out / ("case_00" + std::to_string(c)) / "fractures.csv");
    const std::size_t share = std::find(rows[0].begin(), rows[0].end(), "open_share") - rows[0].begin();
    ASSERT_LT(share, rows[0].size());
    std::set<std::string> opening;  // open over some of their length (open_share > 0)
    for (const auto& row : rows)
      if (row[0] == rows.back()[0] && std::stod(row[share]) > 0.0) opening.insert(row[2]);
    EXPECT_EQ(opening, listed[c]) << "case " << c;
  }
  fs::remove_all(out);
}

}  // namespace
