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
#include <utility>
#include <vector>

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

// The tutorial's strip model (docs/tutorial_intact_seal.md, section 5: triangles of 0.25 m in a
// strip about the flaw, T = 1 MPa, c = 3.2 MPa) from the in-situ state at 1,300 m of head, one
// pass. A corner of a sub-block by the flaw's tip starts a DDA step 1.07 µm into a face, 14
// times the penetration tolerance, held by the locked contacts of the bonded cells about it:
// each Lagrangian pass took 2–4% off its overlap, the step's tries ran out of passes and every
// cut failed alike, and the run stopped in its first pass on "the time step fell below any use"
// (docs/studies/2026-11-30-strip-seal-lagrangian.md). With the multipliers mixed before a cut
// (docs/dda.md) the pass runs through, bonds breaking about the tip.
TEST(IntactSeal, TheStripModelsFirstPassAt1300MRunsThroughAsBondsBreakAboutTheTip) {
  std::string text = read_text(kSeal);
  int count = 0;
  const std::string strip = "[[geometry.tessellate]]\nkind = \"triangles\"\nsize = 0.25\n"
                            "region = [[5.0, 2.0], [7.0, 2.0], [7.0, 7.0], [5.0, 7.0]]\njoint = \"mudstone\"\n"
                            "seed = 5\ncracks = [[[6.0, 2.0], [6.0, 5.0]]]\n\n";
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"cracks = [[[6.0, 2.0], [6.0, 5.0]]]   # a flaw from the reservoir, 3 m up into the seal\n", ""},
           {"[[geometry.tessellate]]               # the intact lower seal: bonded triangles", strip + "[[geometry.tessellate]]"},
           {"tensile_strength = 2.0e6", "tensile_strength = 1.0e6"},
           {"cohesion = 6.0e6", "cohesion = 3.2e6"},
           {"head = 500.0 ", "head = 1300.0 "},
           {"max_iterations = 30", "max_iterations = 1"}}) {
    text = replace_all(text, from, to, count);
    EXPECT_EQ(count, 1) << from;
  }
  const RunResult r = run_text_and_read(text, "intact-seal-strip-1300");
  ASSERT_TRUE(r.summary.contains("iterations")) << r.summary.dump();
  EXPECT_EQ(r.summary["iterations"], 1);
  EXPECT_EQ(r.summary["status"], "ok");
  const std::string message = r.summary["message"];
  EXPECT_EQ(message.find("time step fell below"), std::string::npos) << message;
  const int broken = column_of(r.history.front(), "broken_bonds");
  ASSERT_GE(broken, 0);
  EXPECT_GT(std::stoi(r.history.at(1).at(static_cast<std::size_t>(broken))), 0);
}

}  // namespace
}  // namespace hydrodda::testing::coupled
