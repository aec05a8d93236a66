// Coupled transient runs by the fixed-stress split, through the real program on
// scenarios/verification/terzaghi_consolidation.toml (docs/coupling.md, "Coupled transient runs"):
// a 10 m column of twenty blocks between rollers, drained at its top, loaded by σ = 1 MPa at
// t = 0. Reference: Terzaghi's series (Verruijt, Theory and Problems of Poroelasticity, ch. 2;
// Wang 2000, §6.2), with K_v = E(1 − ν)/((1 + ν)(1 − 2ν)) = 1.2e9 Pa the constrained modulus
// in plane strain, c_v = k/(μ (S + α²/K_v)), T = c_v t/H², z the depth below the top:
//   p(z, t) = p0 Σ_m (2/M) sin(M z/H) exp(−M² T),   M = (2m + 1)π/2,  p0 = α σ/(α² + S K_v),
//   s(t) = s0 + (s∞ − s0) [1 − Σ_m (2/M²) exp(−M² T)],  s0 = (σ − α p0) H/K_v,  s∞ = σ H/K_v.
// Tolerances: the pressure at 2.5, 5 and 10 m depth within 2% of p0 and the settlement within
// 2% of s∞ − s0, at T = 0.05, 0.1, 0.3 and 1 (measured: 1.4% and 0.9% at worst, the pressure
// near the top early, where the block's face has settled below the drained boundary of the
// fixed mesh; docs/studies/2026-11-29-terzaghi-consolidation.md); the first step's pressure
// at the base, undrained, within 0.5% of p0 (measured 0.32%).

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "coupled_runs.hpp"
#include "terzaghi_series.hpp"

using namespace hydrodda::testing::coupled;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;
using namespace hydrodda::testing::terzaghi;

namespace {

struct Consolidation {
  nlohmann::json summary;
  std::vector<std::vector<std::string>> history, probes, measure;
};

Consolidation run_column(const std::string& text, const std::string& name) {
  const fs::path file = fs::temp_directory_path() / ("hydrodda-consolidation-" + name + ".toml");
  const fs::path out = fs::temp_directory_path() / ("hydrodda-consolidation-" + name);
  std::ofstream(file) << text;
  fs::remove_all(out);
  const auto result = run_program("run " + file.string() + " -o " + out.string() + " --threads 1");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  Consolidation c;
  if (std::ifstream in(out / "summary.json"); in) c.summary = nlohmann::json::parse(in);
  c.history = read_csv(out / "history.csv");
  c.probes = read_csv(out / "probes.csv");
  c.measure = read_csv(out / "measure.csv");
  fs::remove_all(out);
  fs::remove(file);
  return c;
}

TEST(CoupledTransientVerification, AColumnOfBlocksConsolidatesAsTerzaghisSeries) {
  const Consolidation c = run_column(read_text(kVerification / "terzaghi_consolidation.toml"), "terzaghi");
  EXPECT_EQ(c.summary["converged"], true);
  EXPECT_DOUBLE_EQ(c.summary["time"].get<double>(), 1.4e5);
  const std::map<std::string, double> depth{{"z2.5", 2.5}, {"z5", 5.0}, {"z10", 10.0}};
  int pressures = 0, settlements = 0;
  for (std::size_t r = 1; r < c.probes.size(); ++r) {
    const double t = std::stod(c.probes[r][0]);
    const double p = std::stod(c.probes[r][3]);
    if (t == 50.0 && c.probes[r][1] == "z10") {
      EXPECT_NEAR(p / kP0, 1.0, 0.005) << "undrained at the first step";
    }
    if (t != 4667.0 && t != 9333.0 && t != 2.8e4 && t != 9.333e4) continue;
    EXPECT_NEAR(p, series_pressure(depth.at(c.probes[r][1]), t), 0.02 * kP0) << c.probes[r][1] << " at t = " << t;
    ++pressures;
  }
  for (std::size_t r = 1; r < c.measure.size(); ++r) {
    const double t = std::stod(c.measure[r][1]);
    if (t != 4667.0 && t != 9333.0 && t != 2.8e4 && t != 9.333e4) continue;
    EXPECT_NEAR(-std::stod(c.measure[r][6]), series_settlement(t), 0.02 * (kSinf - kS0)) << "settlement at t = " << t;
    ++settlements;
  }
  EXPECT_EQ(pressures, 12);
  EXPECT_EQ(settlements, 4);
}

// Mikelić & Wheeler (2013): with β = α²/K_dr the fixed-stress iteration contracts at a rate no
// worse than (β − α²/K_v)/(S + β) ≤ 1 − K_dr/K_v = 1/3 here (ν = 0.25, plane strain), whatever
// the coupling strength α²/(S K_dr): a head change from 1 to the tolerance 1e-6 takes at most
// log(1e-6)/log(1/3) ≈ 12.6 iterations after the first. The strength raised 100× (S from 1e-9
// to 1e-11 1/Pa: 1.25 to 125), every step converges within 15 iterations, and the mean
// iterations per step at the strongest coupling are within 15% of those at the middle one
// (measured 10.2 and 9.6; 7.2 at the weakest, where S itself damps the iteration).
TEST(CoupledTransientVerification, FixedStressIterationsStayFlatAsTheCouplingStrengthGrows100Times) {
  std::vector<double> means;
  for (const std::string storage : {"1.0e-9", "1.0e-10", "1.0e-11"}) {
    std::string text = read_text(kVerification / "terzaghi_consolidation.toml");
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"storage = 1.0e-10", "storage = " + storage},
             {"end_time = 1.4e5", "end_time = 2.0e4"},
             {"output_times = [4.667e3, 9.333e3, 2.8e4, 9.333e4]", "output_times = [1.0e4]"},
             {"figures = [\"png\"]", "figures = []"}}) {
      int edits = 0;
      text = replace_all(text, from, to, edits);
      ASSERT_EQ(edits, 1) << from;
    }
    const Consolidation c = run_column(text, "strength-" + storage);
    EXPECT_EQ(c.summary["converged"], true) << storage;
    const int column = column_of(c.history[0], "iterations");
    double total = 0.0;
    for (std::size_t r = 2; r < c.history.size(); ++r) {  // the header and t = 0 left out
      const int iterations = std::stoi(c.history[r][column]);
      EXPECT_LE(iterations, 15) << "S = " << storage << ", step " << c.history[r][0];
      total += iterations;
    }
    means.push_back(total / static_cast<double>(c.history.size() - 2));
  }
  ASSERT_EQ(means.size(), 3u);
  EXPECT_LT(means[2], 1.15 * means[1]) << means[1] << " → " << means[2];
}

// A step whose iterations cannot converge (coupling.max_iterations = 3 against the ~13 the
// column needs) is cut by half and retried down to the floor time_step/2^10, and the run then
// ends not converged at t = 0, saying so and why: never a false "converged", never an abort.
TEST(CoupledTransientVerification, AStepThatCannotConvergeIsCutToTheFloorAndTheRunSaysWhenAndWhy) {
  int edits = 0;
  const std::string text = replace_all(read_text(kVerification / "terzaghi_consolidation.toml"),
                                       "max_iterations = 40", "max_iterations = 3", edits);
  ASSERT_EQ(edits, 1);
  const Consolidation c = run_column(text, "floor");
  EXPECT_EQ(c.summary["converged"], false);
  EXPECT_DOUBLE_EQ(c.summary["time"].get<double>(), 0.0);
  const std::string message = c.summary["message"];
  EXPECT_NE(message.find("not converged at t = 0 s"), std::string::npos) << message;
  EXPECT_NE(message.find("after 10 cut(s)"), std::string::npos) << message;
  EXPECT_NE(message.find("did not converge in 3 (coupling.max_iterations"), std::string::npos) << message;
  EXPECT_EQ(c.history.size(), 2u) << "the header and t = 0 only";
}

}  // namespace
