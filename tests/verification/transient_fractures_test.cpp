// The fractures and loads of a coupled transient run in time, through the real program. On
// scenarios/verification/terzaghi_consolidation.toml: fractures.csv has a row per fracture per
// step, and each horizontal joint of the consolidating column carries the effective stress of
// Terzaghi's solution at its depth. With σ the load on the top and p the pore pressure (Terzaghi's
// series, Verruijt, Theory and Problems of Poroelasticity, ch. 2; Wang 2000 §6.2; α = 1):
//   σ'(z, t) = σ − p(z, t),   p(z, t) = p0 Σ_m (2/M) sin(M z/H) exp(−M² T),  M = (2m + 1)π/2,
// T = c_v t/H², p0 = σ/(1 + S K_v), c_v = k/(μ (S + 1/K_v)), K_v = E(1 − ν)/((1 + ν)(1 − 2ν)).
// The joints' normal_stress (their contacts' force over their length) within 2% of σ at depths
// 2.5, 5 and 7.5 m at T = 0.05, 0.1, 0.3 and 1 (measured: 1.15% at worst, at 2.5 m from the
// bottom at T = 1; the pressure itself is within 1.4% of p0: docs/coupling.md).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include "coupled_runs.hpp"
#include "terzaghi_series.hpp"

using namespace hydrodda::testing::coupled;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;
using namespace hydrodda::testing::terzaghi;

namespace {

TEST(CoupledTransientFractures, TheColumnsJointsCarryTerzaghisEffectiveStressAtEveryStep) {
  const fs::path out = fs::temp_directory_path() / "hydrodda-transient-fractures";
  fs::remove_all(out);
  const auto result =
      run_program("run " + (kVerification / "terzaghi_consolidation.toml").string() + " -o " + out.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto history = read_csv(out / "history.csv");
  const auto fractures = read_csv(out / "fractures.csv");
  ASSERT_GE(history.size(), 2u);
  const auto& header = fractures[0];
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t time = column("time"), id = column("fracture"), stress = column("normal_stress"),
                    open = column("open");
  ASSERT_LT(stress, header.size());
  // 19 joints, a row each at t = 0 and after every step (history.csv's rows).
  EXPECT_EQ(fractures.size() - 1, 19 * (history.size() - 1));
  // Each time of Terzaghi's (T = 0.05 … 1) is an output time the steps land on.
  std::set<std::pair<double, double>> checked;  // (T, depth)
  for (const double big_t : {0.05, 0.1, 0.3, 1.0}) {
    const double t = big_t * kHeight * kHeight / kCv;
    for (std::size_t r = 1; r < fractures.size(); ++r) {
      const auto& row = fractures[r];
      const double at = std::stod(row[time]);
      if (std::abs(at - t) > 1e-3 * t) continue;
      const double y = 0.5 * (std::stoi(row[id]) + 1);  // the joints every 0.5 m from y = 0.5 m
      const double depth = kHeight - y;
      EXPECT_EQ(row[open], "0") << "joint at y = " << y;
      if (std::abs(depth - 2.5) > 1e-9 && std::abs(depth - 5.0) > 1e-9 && std::abs(depth - 7.5) > 1e-9) continue;
      const double expected = kLoad - series_pressure(depth, at);
      EXPECT_NEAR(std::stod(row[stress]), expected, 0.02 * kLoad) << "depth " << depth << " m, T = " << big_t;
      checked.insert({big_t, depth});
    }
  }
  EXPECT_EQ(checked.size(), 12u);  // three depths at four times
  fs::remove_all(out);
}

// Loads over time in a coupled transient run: a boundary's flux table is read in real time at
// the end of each step, and the steps land on its rows. A column of two blocks, drained at its
// top, pumped at its base by q(t) = 1e-9 m/s × min(t / 100 s, 1) (rows at 0, 100 and 300 s):
// the flow in by the base, from the residual of the assembled system, is q(t) × 1 m of width at
// every step to 1e-9 of it (round-off), and a step ends at t = 100 s exactly.
TEST(CoupledTransientLoads, AFluxTableIsReadInRealTimeAtTheEndOfEachStep) {
  const fs::path dir = fs::temp_directory_path() / "hydrodda-transient-flux-table";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "column.toml") << R"(
[geometry]
domain = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0], [0.0, 2.0]]
fractures = [ [[0.0, 1.0], [1.0, 1.0]] ]
initial_aperture = 0.0
[material.rock]
density = 2000.0
young = 1.0e9
poisson = 0.25
permeability = 1.0e-14
storage = 1.0e-9
[joint]
friction_angle = 30.0
[mechanics]
gravity = [0.0, 0.0]
time_step = 1.0
steps = 2
[[mechanics.roller]]
boundary = "left"
[[mechanics.roller]]
boundary = "right"
[[mechanics.roller]]
boundary = "bottom"
[[mechanics.traction]]
boundary = "top"
normal = -1.0e5
[flow]
pressure = "overpressure"
[[flow.boundary]]
name = "bottom"
flux = [[0.0, 0.0], [100.0, -1.0e-9], [300.0, -1.0e-9]]
[[flow.boundary]]
name = "top"
head = 0.0
[flow.transient]
end_time = 300.0
time_step = 7.0
max_time_step = 30.0
initial_head = 0.0
[mesh]
size = 0.25
[output]
figures = []
)";
  const auto result = run_program("run " + (dir / "column.toml").string() + " -o " + (dir / "out").string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto history = read_csv(dir / "out" / "history.csv");
  const auto& header = history[0];
  const std::size_t time = std::find(header.begin(), header.end(), "time") - header.begin();
  const std::size_t flow = std::find(header.begin(), header.end(), "flow_bottom") - header.begin();
  ASSERT_LT(flow, header.size());
  bool landed = false;
  for (std::size_t r = 2; r < history.size(); ++r) {
    const double t = std::stod(history[r][time]);
    const double expected = -1.0e-9 * std::min(t / 100.0, 1.0);
    EXPECT_NEAR(std::stod(history[r][flow]), expected, 1e-9 * 1e-9) << "t = " << t;
    landed = landed || t == 100.0;
  }
  EXPECT_TRUE(landed);
  EXPECT_EQ(std::stod(history.back()[time]), 300.0);
  fs::remove_all(dir);
}

}  // namespace
