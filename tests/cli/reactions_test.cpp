// A prescribed displacement's reaction in history.csv: what a load frame reads.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;
using hydrodda::testing::scratch_folder;

namespace {

// history.csv's last row, by column name.
std::map<std::string, double> last_row(const fs::path& file) {
  const auto table = hydrodda::testing::read_csv(file);
  std::map<std::string, double> row;
  for (std::size_t c = 0; c < table.front().size(); ++c) row[table.front()[c]] = std::stod(table.back().at(c));
  return row;
}

// A block W = 2 m wide and H = 1 m high on a frictionless fixed base, its top pushed down by
// δ = 1 mm over 10 steps and held for 10 more (plane stress, no gravity). The top's two
// vertices are held in x too, so the block, whose strain is uniform, cannot widen: εx = 0,
// σyy = E εy / (1 − ν²), σxx = ν σyy. The frame's vertical reaction on the rock balances the
// block's stress over its top, R_y = σyy W (an identity of the static equilibrium at rest), and
// the two horizontal ones cancel.
constexpr char kPushedBlock[] = R"(title = "A block pushed down 1 mm by its top on a frictionless base"
[geometry]
[[geometry.block]]
vertices = [[-1.0, -1.0], [3.0, -1.0], [3.0, 0.0], [-1.0, 0.0]]
fixed = true
[[geometry.block]]
vertices = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]
[boundaries]
lid = { from = [0.0, 1.0], to = [2.0, 1.0] }
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[joint]
friction_angle = 0.0
[mechanics]
analysis = "static"
plane = "stress"
gravity = [0.0, 0.0]
time_step = 1.0
steps = 20
[[mechanics.displacement]]
boundary = "lid"
value = [0.0, -1.0e-3]
ramp_time = 10.0
[output]
figures = []
)";

TEST(Reactions, APushedBlocksReactionBalancesItsStressAndMatchesItsStiffness) {
  const fs::path dir = scratch_folder();
  std::ofstream(dir / "pushed.toml") << kPushedBlock;
  const auto result = run_program("run " + (dir / "pushed.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto row = last_row(dir / "out/history.csv");
  ASSERT_TRUE(row.count("reaction_x_lid") && row.count("reaction_y_lid"));
  const auto summary = nlohmann::json::parse(std::ifstream(dir / "out/summary.json"));
  const nlohmann::json& block = summary["blocks"][1];
  const double sigma_yy = block["stress"][1];
  constexpr double kWidth = 2.0, kYoung = 1.0e10, kPoisson = 0.25, kPushed = 1.0e-3;
  // Equilibrium at rest: to the augmented Lagrangian's precision, 1e-6 of the force.
  EXPECT_NEAR(row.at("reaction_y_lid"), sigma_yy * kWidth, 1e-6 * std::abs(sigma_yy * kWidth));
  EXPECT_NEAR(row.at("reaction_x_lid"), 0.0, 1e-6 * std::abs(sigma_yy * kWidth));
  // The stiffness: −E δ W / ((1 − ν²) H) = −2.133e7 N/m, within 1%: the springs that impose
  // the displacement (10 × the penalty) and the base contact yield by some 1/500 of it.
  const double expected = -kYoung * kPushed * kWidth / (1.0 - kPoisson * kPoisson);
  EXPECT_NEAR(row.at("reaction_y_lid"), expected, 0.01 * std::abs(expected));
}

TEST(Reactions, EachDefinitionHasItsOwnColumnsAndARunWithoutAnyHasNone) {
  const fs::path dir = scratch_folder();
  std::string two = kPushedBlock;
  // Two more tables asking the same motion as the first: the top's middle, and the lid again.
  two += "[[mechanics.displacement]]\npoint = [1.0, 1.0]\nvalue = [0.0, -1.0e-3]\nramp_time = 10.0\n"
         "[[mechanics.displacement]]\nboundary = \"lid\"\nvalue = [0.0, -1.0e-3]\nramp_time = 10.0\n";
  // The last two tables are appended after [output]: give them back to [mechanics].
  const std::string output_table = "[output]\nfigures = []\n";
  two.replace(two.find(output_table), output_table.size(), "");
  two += output_table;
  std::ofstream(dir / "two.toml") << two;
  const auto result = run_program("run " + (dir / "two.toml").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream in(dir / "out/history.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find(",reaction_x_lid_1,reaction_y_lid_1,reaction_x_point_2,reaction_y_point_2,"
                        "reaction_x_lid_3,reaction_y_lid_3"),
            std::string::npos)
      << header;

  std::string none = kPushedBlock;
  none.replace(none.find("[[mechanics.displacement]]"), none.find("[output]") - none.find("[[mechanics.displacement]]"),
               "[[mechanics.fixed]]\npoint = [1.0, 0.5]\n");
  std::ofstream(dir / "none.toml") << none;
  const auto fixed = run_program("run " + (dir / "none.toml").string() + " -o " + (dir / "fixed").string());
  ASSERT_EQ(fixed.exit_code, 0) << fixed.output;
  std::ifstream fixed_history(dir / "fixed/history.csv");
  std::getline(fixed_history, header);
  EXPECT_EQ(header.find("reaction"), std::string::npos) << header;
}

}  // namespace
