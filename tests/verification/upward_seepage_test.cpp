// A column of blocks under upward seepage (Terzaghi's heave), through the real program on
// scenarios/verification/coupled_upward_seepage_column.toml (docs/coupling.md, "Verification").
// Reference: Terzaghi's effective stress under an upward gradient i (Theoretical Soil
// Mechanics, 1943, §"heave"; α = 1, the seepage force −∇p on the skeleton):
//   σ'yy(y) = −(ρ_r − ρ_w (1 + i)) g (10 − y),   zero at i_c = (ρ_r − ρ_w)/ρ_w = 1.5,
// each block's uniform stress the mean over it, i.e. the value at its centroid as built.
// Tolerances: below i_c every block within 1e-5 of it (measured 2.3e-6 at 0.6 i_c, 1.9e-8 at
// 0.995 i_c: the blocks' elastic shortening) and the column still within 1e-4 m. Above i_c the
// column lifts; it floats where the part still under the water at the top is held up by the
// seepage force, (10 − δ)(1 + 10.5 i/(10.5 − δ)) = 10 ρ_r/ρ_w, δ = 0.279 m at 1.02 i_c,
// 0.694 m at 1.05 i_c. On a uniform mesh of size h the loop reaches a float above it by about
// h/2 (the elements the lifted base crosses, part gap and part rock, take nearly the gap's
// permeability: docs/coupling.md, "A group that floats"): within 0.6 h at h = 0.025 m
// (measured 0.45 h and 0.48 h), and its error at least halved from h = 0.05 m (measured a
// third).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupled_runs.hpp"

using namespace hydrodda::testing::coupled;

namespace {

constexpr double kCriticalGradient = (kRhoRock - kRhoWater) / kRhoWater;

// The scenario at gradient `ratio` × i_c: the bottom head 10 + 10.5 i m (the top's is 10 m).
std::string column_at(double ratio, int passes) {
  const std::string text = read_text(kVerification / "coupled_upward_seepage_column.toml");
  int heads = 0, limits = 0;
  std::string scenario =
      replace_all(text, "head = 19.45", "head = " + std::to_string(10.0 + 10.5 * kCriticalGradient * ratio), heads);
  scenario = replace_all(scenario, "max_iterations = 30", "max_iterations = " + std::to_string(passes), limits);
  EXPECT_EQ(heads, 1);
  EXPECT_EQ(limits, 1);
  return scenario;
}

TEST(CoupledVerification, AColumnUnderUpwardSeepageCarriesTerzaghisEffectiveStress) {
  for (const double ratio : {0.6, 0.995}) {
    const double i = ratio * kCriticalGradient;
    const RunResult r = run_text_and_read(column_at(ratio, 30), "seepage-column-" + std::to_string(ratio));
    EXPECT_EQ(r.summary["converged"], true) << ratio << " i_c: a column at rest is an equilibrium";
    const double lift = r.summary["measure"]["top"]["displacement"][1];
    EXPECT_LT(std::abs(lift), 1e-4) << ratio << " i_c: the column must lie still";
    int checked = 0;
    for (const auto& block : r.summary["blocks"]) {
      const double y = double(block["centroid"][1]) - double(block["displacement"][1]);  // as built
      if (y < 0.0) continue;  // the fixed base
      const double terzaghi = -(kRhoRock - kRhoWater * (1.0 + i)) * kG * (10.0 - y);
      const double syy = block["stress"][1];
      EXPECT_NEAR(syy / terzaghi, 1.0, 1e-5) << ratio << " i_c, block " << block["id"] << " at y = " << y;
      ++checked;
    }
    EXPECT_EQ(checked, 10);
  }
}

// The float height δ at gradient ratio × i_c, by bisection of
// (10 − δ)(1 + 10.5 i/(10.5 − δ)) = 10 ρ_r/ρ_w on (0, 5) m (the left side falls with δ there).
double float_height(double ratio) {
  const double i = ratio * kCriticalGradient;
  const auto excess = [&](double d) { return (10.0 - d) * (1.0 + 10.5 * i / (10.5 - d)) - 10.0 * kRhoRock / kRhoWater; };
  double low = 0.0, high = 5.0;
  for (int k = 0; k < 60; ++k) (excess(0.5 * (low + high)) > 0.0 ? low : high) = 0.5 * (low + high);
  return 0.5 * (low + high);
}

// The column at ratio × i_c on a uniform mesh of size h: its float's error (m) against the
// formula, the run converged within `passes`, the column whole (every block lifted alike).
double float_error(double ratio, double h, int passes) {
  int sizes = 0, fracture_sizes = 0;
  std::string text = replace_all(column_at(ratio, 30), "size = 0.25\n", "size = " + std::to_string(h) + "\n", sizes);
  text = replace_all(text, "fracture_size = 0.1\n", "fracture_size = " + std::to_string(h) + "\n", fracture_sizes);
  EXPECT_EQ(sizes, 1);
  EXPECT_EQ(fracture_sizes, 1);
  const RunResult r = run_text_and_read(text, "seepage-column-float-" + std::to_string(ratio) + "-" + std::to_string(h));
  EXPECT_EQ(r.summary["converged"], true) << ratio << " i_c on h = " << h << ": " << r.summary["message"];
  EXPECT_LE(int(r.summary["iterations"]), passes) << ratio << " i_c on h = " << h;
  const double lift = r.summary["measure"]["top"]["displacement"][1];
  for (const auto& block : r.summary["blocks"])
    if (double(block["centroid"][1]) - double(block["displacement"][1]) > 0.0)  // not the base
      EXPECT_NEAR(double(block["displacement"][1]), lift, 1e-4) << "block " << block["id"] << ": the column whole";
  return lift - float_height(ratio);
}

TEST(CoupledVerification, AColumnPastTheCriticalGradientFloatsWhereTheSeepageForceHoldsItUp) {
  const double coarse = float_error(1.02, 0.05, 25);
  const double fine = float_error(1.02, 0.025, 15);
  EXPECT_GT(fine, 0.0) << "the part-gap elements at the lifted base raise the float";
  EXPECT_LT(fine, 0.6 * 0.025) << "1.02 i_c on h = 0.025 m: float at " << float_height(1.02) + fine;
  EXPECT_LT(fine, 0.5 * coarse) << "the float must converge with the mesh";
  const double steeper = float_error(1.05, 0.025, 15);
  EXPECT_GT(steeper, 0.0);
  EXPECT_LT(steeper, 0.6 * 0.025) << "1.05 i_c on h = 0.025 m: float at " << float_height(1.05) + steeper;
}

TEST(CoupledVerification, AColumnPastTheCriticalGradientRisesTowardsItsFloatAndSaysItNeverCameToRest) {
  // 30 passes at 1.02 i_c on the shipped mesh, whose 0.24 m elements where the base lifts to
  // resolve no float (the lowest blocks, their base in part-gap elements, fall back while the
  // rest rises: docs/coupling.md, "Upward seepage through a column"): the column rises towards
  // its floating height, 0.279 m, never at rest.
  const RunResult r = run_text_and_read(column_at(1.02, 30), "seepage-column-1.02");
  EXPECT_EQ(r.summary["converged"], false) << "a column still rising is no equilibrium";
  const double lift = r.summary["measure"]["top"]["displacement"][1];
  EXPECT_GT(lift, 0.1) << "the column must have lifted";
  EXPECT_LT(lift, 1.1 * 0.279) << "nor risen past where it floats";
  const std::string message = r.summary["message"];
  EXPECT_NE(message.find("the blocks came to rest in none of the last"), std::string::npos) << message;
  EXPECT_EQ(message.find("try coupling.acceleration"), std::string::npos) << message;
  EXPECT_NE(message.find("farthest from where they started: block"), std::string::npos) << message;
}

}  // namespace
