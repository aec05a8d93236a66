// The load ramp of the overpressure alone (coupling.ramp = "overpressure", docs/coupling.md,
// "Relaxation, acceleration and the load ramp"), through the real program on
// scenarios/verification/coupled_hydrostatic_column.toml (three 1 m blocks, Biot 0, the base
// block held by its corners, the hydrostatic convention) and on a block that floats against a
// lid (tests/verification/data/floating_block.toml).
// References: Archimedes' buoyancy and the load of pass k, p_k = p_s + r_k (p − p_s),
// r_k = min(1, k / n), p_s the still water at the lowest fixed head. Under an upward seepage
// (heads 3 + ΔH at the bottom, 3 m at the top, the head linear in y) the interface at y carries
//   overpressure ramp: N_k(y) = g (3 − y) [ρ_r − ρ_w − r_k ρ_w ΔH / 3],
//   whole ramp:        N_k(y) = g (3 − y) [ρ_r − r_k ρ_w (1 + ΔH / 3)],
// within 1% (the contacts' forces at rest after each pass; the faces integrate the P1 pressure,
// exact for this linear one, as in hydrostatic_column_test.cpp).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "coupled_runs.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::read_csv;
using hydrodda::testing::read_file_bytes;
using hydrodda::testing::run_program;
using namespace hydrodda::testing::coupled;

namespace {

// The column with its bottom head, density and ramp replaced; `ramp` "" leaves coupling.ramp out.
std::string column(double bottom_head, double density, const std::string& ramp) {
  int count = 0;
  std::string text = read_text(kVerification / "coupled_hydrostatic_column.toml");
  text = replace_all(text, "name = \"bottom\"\nhead = 3.0", "name = \"bottom\"\nhead = " + std::to_string(bottom_head), count);
  EXPECT_EQ(count, 1);
  text = replace_all(text, "density = 2500.0", "density = " + std::to_string(density), count);
  EXPECT_EQ(count, 1);
  text = replace_all(text, "figures = []", "figures = []\nevery = 1", count);
  EXPECT_EQ(count, 1);
  text = replace_all(text, "max_iterations = 10",
                     "max_iterations = 10\nramp_passes = 3" + (ramp.empty() ? "" : "\nramp = \"" + ramp + "\""), count);
  EXPECT_EQ(count, 1);
  return text;
}

// Runs `scenario` into a fresh folder, kept for the caller to read pass by pass.
fs::path run_kept(const std::string& scenario, const std::string& name, int exit_code = 0) {
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-overpressure-ramp-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scenario.toml") << scenario;
  const auto result = run_program("run " + (dir / "scenario.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, exit_code) << result.output;
  return dir / "out";
}

std::string contacts_of_pass(const fs::path& out, int pass) {
  char file[32];
  std::snprintf(file, sizeof file, "contacts_%04d.vtu", pass);
  return read_file_bytes(out / file);
}

TEST(OverpressureRamp, EachPassLoadsTheColumnWithStillWaterAndItsShareOfTheOverpressure) {
  const double delta_h = 2.0;  // i = 2/3, under the critical gradient 1.5: the column stays put
  for (const std::string ramp : {"overpressure", "whole"}) {
    const fs::path out = run_kept(column(3.0 + delta_h, kRhoRock, ramp), "column-" + ramp);
    const auto history = read_csv(out / "history.csv");
    const int load = column_of(history[0], "load_factor");
    ASSERT_GE(load, 0);
    ASSERT_GE(history.size(), 5u) << "three ramped passes and one at the full load at least";
    for (int pass = 1; pass <= 4; ++pass) {
      const double r = std::min(1.0, pass / 3.0);
      EXPECT_NEAR(std::stod(history[pass][load]), r, 1e-12) << ramp << ", pass " << pass;
      const std::array<double, 3> n = sum_interface_forces(contacts_of_pass(out, pass), false);
      for (int y = 1; y <= 2; ++y) {
        const double over = kG * (3.0 - y) * (kRhoRock - kRhoWater - r * kRhoWater * delta_h / 3.0);
        const double whole = kG * (3.0 - y) * (kRhoRock - r * kRhoWater * (1.0 + delta_h / 3.0));
        const double expected = ramp == "overpressure" ? over : whole;
        EXPECT_NEAR(n[y], expected, 0.01 * expected) << ramp << ", pass " << pass << ", interface y = " << y;
      }
    }
    fs::remove_all(out.parent_path());
  }
}

// A block lighter than water (500 kg/m3, Biot 0) floats up against a lid held by its top
// corners, in still water (heads 3 m and 3 m over a 1 m x 2 m domain): the lid's base carries
// the block's net buoyancy (ρ_w − ρ_b) g × 1 m² = 4,905 N. Ramped from still water every pass
// loads it with the whole of it: the lid carries 4,905 N within 1% in each pass and the block
// stays against it (within 1e-5 m: the contact's and the blocks' elastic give), converged.
// Ramped from no water, pass 1's buoyancy is a third of it, 1,635 N under the block's 4,905 N
// weight: it sinks, farther than its own size, and the run ends "no equilibrium" (exit 1).
TEST(OverpressureRamp, ABlockTheStillWaterFloatsKeepsFloatingWhereTheWholeRampSinksIt) {
  const std::string scenario = read_text(fs::path(HYDRODDA_SOURCE_DIR) / "tests/verification/data/floating_block.toml");
  int count = 0;
  const std::string whole = replace_all(scenario, "\nramp = \"overpressure\"", "\nramp = \"whole\"", count);
  ASSERT_EQ(count, 1);

  const fs::path out = run_kept(scenario, "float-overpressure");
  const auto measure = read_csv(out / "measure.csv");
  const int uy = column_of(measure[0], "uy");
  ASSERT_GE(uy, 0);
  ASSERT_GE(measure.size(), 5u) << "three ramped passes and one at the full load at least";
  for (std::size_t row = 1; row < measure.size(); ++row) {
    EXPECT_LE(std::abs(std::stod(measure[row][uy])), 1e-5) << "pass " << measure[row][0];
    const double lid = sum_interface_forces(contacts_of_pass(out, static_cast<int>(row)), false)[1];
    const double net_buoyancy = (kRhoWater - 500.0) * kG * 1.0;
    EXPECT_NEAR(lid, net_buoyancy, 0.01 * net_buoyancy) << "pass " << row;
  }
  std::ifstream in(out / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(in)["converged"], true);
  fs::remove_all(out.parent_path());

  const fs::path sunk = run_kept(whole, "float-whole", 1);
  std::ifstream sunk_summary(sunk / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(sunk_summary)["status"], "no equilibrium");
  const auto sunk_measure = read_csv(sunk / "measure.csv");
  ASSERT_GE(sunk_measure.size(), 2u);
  EXPECT_LT(std::stod(sunk_measure[1][uy]), -1.0) << "pass 1 sinks the block";
  fs::remove_all(sunk.parent_path());
}

}  // namespace
