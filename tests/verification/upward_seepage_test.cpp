// A column of blocks under upward seepage (Terzaghi's heave), through the real program on
// scenarios/verification/coupled_upward_seepage_column.toml (docs/coupling.md, "Verification").
// Reference: Terzaghi's effective stress under an upward gradient i (Theoretical Soil
// Mechanics, 1943, §"heave"; α = 1, the seepage force −∇p on the skeleton):
//   σ'yy(y) = −(ρ_r − ρ_w (1 + i)) g (10 − y),   zero at i_c = (ρ_r − ρ_w)/ρ_w = 1.5,
// each block's uniform stress the mean over it, i.e. the value at its centroid as built.
// Tolerances: below i_c every block within 1e-5 of it (measured 2.3e-6 at 0.6 i_c, 1.9e-8 at
// 0.995 i_c: the blocks' elastic shortening) and the column still within 1e-4 m. Above i_c the
// column lifts; it floats where the part still under the water at the top is held up by the
// seepage force, (10 − δ)(1 + 10.5 i/(10.5 − δ)) = 10 ρ_r/ρ_w, δ = 0.279 m at 1.02 i_c.

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

TEST(CoupledVerification, AColumnPastTheCriticalGradientRisesTowardsItsFloatAndSaysItNeverCameToRest) {
  // 30 passes at 1.02 i_c: the column rises about 0.012 m a pass (static DDA moves a body that
  // nothing holds by F Δt²/2M a step) towards its floating height, 0.279 m, never at rest.
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
