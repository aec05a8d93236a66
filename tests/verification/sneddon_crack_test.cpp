// A crack of broken bonds held at a pressure by the flow, through the program, on
// scenarios/verification/sneddon_crack.toml (a crack of half-length a = 1 m, pre-broken bonds of
// a plate of bonded triangle sub-blocks, a/10 about the crack, reached by the flow at its centre
// through an inlet held at p = 1 MPa, in a matrix of 1e-20 m²; its far sides at p = 0):
// - the broken bonds conduct: the crack stands at the inlet's pressure along its length (within
//   1% of p at 0.5 a and 0.95 a: its transmissivity (1e-5 m)³/12 against the matrix's leak),
//   where the same plate with the bonds intact (no `cracks`) is rock and the matrix's pressure
//   falls by more than a third over the same length (measured: 0.99999 p cracked, 0.45 p intact);
// - the crack opens as Sneddon's (1946; Sneddon & Lowengrub 1969), plane strain,
//     w(s) = 4 (1 − ν²) p / E √(a² − s²),  w(0) = 0.375 mm (E = 10 GPa, ν = 0.25),
//   within 5% at its centre and at s = a/2 (measured 0.977 and 0.969 of it: the triangles are
//   constant-strain elements, a little stiff at a/10; the plate's finite width, 20 a, opens it
//   some 0.6% more than the infinite one's, Feddersen's √sec(π a / W));
// - the fluid loads the crack's faces and nothing else: the intact plate, loaded on no intact
//   bond's faces, does not open (under 1e-9 m; measured 8e-17 m).
// Convergence with the size and Voronoi cells against triangles:
// docs/studies/2026-11-29-sneddon-crack-at-rest.md.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupled_runs.hpp"

namespace hydrodda::testing::coupled {
namespace {

constexpr double kPressure = 1.0e6;

constexpr double kYoung = 1.0e10;
constexpr double kPoisson = 0.25;
constexpr double kHalfLength = 1.0;

// Sneddon's opening at s from the crack's centre, plane strain.
double sneddon_opening(double s) {
  return 4.0 * (1.0 - kPoisson * kPoisson) * kPressure / kYoung * std::sqrt(kHalfLength * kHalfLength - s * s);
}

double opening_of(const RunResult& r, const std::string& above = "above", const std::string& below = "below") {
  return r.summary["measure"][above]["displacement"][1].get<double>() -
         r.summary["measure"][below]["displacement"][1].get<double>();
}

TEST(SneddonCrack, ACrackOfBrokenBondsHeldByTheFlowConductsAndOpensAsSneddons) {
  const RunResult cracked = run_and_read(kVerification / "sneddon_crack.toml", "sneddon");
  ASSERT_TRUE(cracked.summary.contains("measure"));
  EXPECT_EQ(cracked.summary["converged"], true);
  const PressureField field(cracked.fluid);
  ASSERT_FALSE(field.empty());
  for (const double x : {0.5, 0.95}) EXPECT_NEAR(field.at(x, 0.0), kPressure, 0.01 * kPressure) << "x = " << x;
  EXPECT_NEAR(opening_of(cracked) / sneddon_opening(0.001), 1.0, 0.05);
  EXPECT_NEAR(opening_of(cracked, "above_half", "below_half") / sneddon_opening(0.5), 1.0, 0.05);

  // The same plate, its bonds intact: rock to the flow, and no face for the fluid to load.
  std::string text = read_text(kVerification / "sneddon_crack.toml");
  int count = 0;
  text = replace_all(text, "cracks = [[[0.0, 0.0], [1.0, 0.0]]]\n", "", count);
  ASSERT_EQ(count, 1);
  const RunResult intact = run_text_and_read(text, "sneddon-intact");
  ASSERT_TRUE(intact.summary.contains("measure"));
  const PressureField rock(intact.fluid);
  ASSERT_FALSE(rock.empty());
  EXPECT_LT(rock.at(0.95, 0.0), (2.0 / 3.0) * kPressure);
  EXPECT_LT(std::abs(opening_of(intact)), 1.0e-9);
}

}  // namespace
}  // namespace hydrodda::testing::coupled
