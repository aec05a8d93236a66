// The seal through intact rock (scenarios/examples/seal_through_intact_rock.toml,
// docs/tutorial_intact_seal.md): a mudstone seal whose lower 5 m are intact rock of bonded
// triangles (T = 2 MPa), a vertical flaw of broken bonds rising 3 m into it from the reservoir,
// the overpressure convention at Biot 0 (the rock's stress effective to the hydrostatic pressure;
// the overpressure presses on the faces of the flaw, the joints and the blocks only). Hand
// estimate: the flaw, a dead end the reservoir's water fills, opens once the overpressure passes
// the effective horizontal stress across it, σ'h(z) = K0 (ρ_r − ρ_w) g z, at its middle
// (z = 1006.5 m): 0.5 × 1400 × 9.81 × 1006.5 = 6.912 MPa, an overpressure head of 704.6 m.
// - 54.6 m of head below it (650 m, 0.54 MPa under σ'h) the flaw stays shut: its faces move
//   apart by less than the penetration tolerance (2e-7 m; measured −7.3e-8 m);
// - 45.4 m above it (750 m, 0.45 MPa over σ'h) it opens: by more than 0.1 mm at its middle
//   (measured 0.18 mm: the scale of an opening under a net pressure Δp over a length a,
//   Δp a (1 − ν²)/E = 0.13 mm, where the shut flaw's is under 2e-7 m);
// - at both, no bond breaks and the loop converges with the seal holding: the open flaw ends
//   in 2 m of intact rock, so the seal's K_eff/K_m rises by under 0.1% (measured 2.4450 to
//   2.4460): a flaw that opens is not a breach while the rock above it holds.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "coupled_runs.hpp"

namespace hydrodda::testing::coupled {
namespace {

const fs::path kSeal = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/seal_through_intact_rock.toml";

RunResult run_at_head(const std::string& head, const std::string& name) {
  std::string text = read_text(kSeal);
  int count = 0;
  text = replace_all(text, "head = 500.0 ", "head = " + head + " ", count);
  EXPECT_EQ(count, 1);
  return run_text_and_read(text, name);
}

double flaw_opening(const RunResult& r) {
  return r.summary["measure"]["flaw_right"]["displacement"][0].get<double>() -
         r.summary["measure"]["flaw_left"]["displacement"][0].get<double>();
}

double seal_conductivity(const RunResult& r) {
  return r.summary["flow"]["regions"]["seal"]["normalised_conductivity"].get<double>();
}

// Every pass's broken_bonds column of history.csv is zero.
void expect_no_bond_broken(const RunResult& r) {
  ASSERT_FALSE(r.history.empty());
  const auto& header = r.history.front();
  const auto column = std::find(header.begin(), header.end(), "broken_bonds");
  ASSERT_NE(column, header.end());
  const auto at = static_cast<std::size_t>(column - header.begin());
  for (std::size_t row = 1; row < r.history.size(); ++row) EXPECT_EQ(r.history[row].at(at), "0") << "pass " << row;
}

TEST(IntactSeal, ItsFlawOpensAsTheReservoirPassesTheHorizontalStressAndTheSealStillHolds) {
  const RunResult below = run_at_head("650.0", "intact-seal-650");
  const RunResult above = run_at_head("750.0", "intact-seal-750");
  for (const RunResult* r : {&below, &above}) {
    ASSERT_TRUE(r->summary.contains("measure"));
    EXPECT_EQ(r->summary["converged"], true);
    expect_no_bond_broken(*r);
  }
  EXPECT_LT(flaw_opening(below), 2.0e-7);
  EXPECT_GT(flaw_opening(above), 1.0e-4);
  EXPECT_NEAR(seal_conductivity(above) / seal_conductivity(below), 1.0, 1.0e-3);
}

}  // namespace
}  // namespace hydrodda::testing::coupled
