#include "hydro/permeability_law.hpp"

#include <gtest/gtest.h>

namespace hydrodda::hydro {
namespace {

TEST(KozenyCarman, FormulaCapAndOpenFractures) {
  // k = d² φ³ / (180 (1 − φ)²): φ = 0.1, d = 1.2e-5 → 1.44e-10 × 1e-3 / (180 × 0.81).
  const double expected = 1.44e-10 * 1e-3 / (180.0 * 0.81);
  EXPECT_NEAR(kozeny_carman_permeability(0.1, 1.2e-5, 1.0), expected, 1e-15 * expected);
  // The paper's set-up: the matrix 1e5 times below the capped fracture value (1e5 mD).
  const double cap = 9.869e-11;
  EXPECT_NEAR(cap / kozeny_carman_permeability(0.1, 1.2e-5, cap), 1.0e5, 0.01e5);
  EXPECT_EQ(kozeny_carman_permeability(1.0, 1.2e-5, cap), cap);
  EXPECT_EQ(kozeny_carman_permeability(0.999, 1.2e-5, cap), cap);
  EXPECT_EQ(kozeny_carman_permeability(0.0, 1.2e-5, cap), 0.0);
  EXPECT_THROW(kozeny_carman_permeability(1.5, 1.2e-5, cap), std::invalid_argument);
}

TEST(CubicLaw, TransmissivityIndependentOfElementWidth) {
  // An element of width b across a fracture of aperture w: fraction w/b, and k b = w³/12 + k_m b
  // whatever b (exact to round-off).
  const double w = 1e-3;
  for (double b : {0.5e-3 * 2, 2e-3, 5e-3, 1e-2}) {
    const double k = cubic_law_permeability(w / b, w, 0.0);
    EXPECT_NEAR(k * b, w * w * w / 12.0, 1e-14 * w * w * w);
  }
  EXPECT_EQ(cubic_law_permeability(0.0, w, 3e-18), 3e-18);
}

// The fracture permeability cap: k = k_m + f min(w²/12, k_cap). Below the cap the cubic law
// itself; above it the cap, so the transmissivity k b = w k_cap grows linearly in w (exact
// identities, round-off). The default cap is a 1 cm gap's, (1e-2 m)²/12.
TEST(CubicLaw, TheFracturePermeabilityIsCapped) {
  EXPECT_DOUBLE_EQ(kDefaultFracturePermeabilityCap, 1e-4 / 12.0);
  const double cap = 1e-8, k_m = 1e-19;  // the cap: a gap of √(12e-8) = 0.35 mm
  const double under = 1e-4, over = 1e-3;
  EXPECT_EQ(cubic_law_permeability(0.5, under, k_m, cap), cubic_law_permeability(0.5, under, k_m));
  EXPECT_FALSE(reaches_fracture_cap(under, cap));
  EXPECT_TRUE(reaches_fracture_cap(over, cap));
  for (double b : {2e-3, 1e-2, 0.1}) {
    const double k = cubic_law_permeability(over / b, over, 0.0, cap);
    EXPECT_NEAR(k * b, over * cap, 1e-14 * over * cap) << b;
  }
  // A layer lifted 2.9 m off its base: 0.7 m² uncapped, the cap's 8.3e-6 m² capped.
  EXPECT_NEAR(cubic_law_permeability(1.0, 2.9, k_m), 0.70, 0.01);
  EXPECT_EQ(cubic_law_permeability(1.0, 2.9, k_m, kDefaultFracturePermeabilityCap), k_m + kDefaultFracturePermeabilityCap);
}

// A wedge w = α s carries α³ s² / 12 over a length s from its tip: at s* exactly the matrix's
// k_m (round-off, 1e-12 relative); the symmetric flexure's central joint (α = 1.42e-3, k_m =
// 9.877e-16 m²) gives 2.0 mm (2.035); an angle of zero or less has no tip.
TEST(CubicLaw, TipLengthIsWhereTheJointCarriesWhatTheMatrixDoes) {
  for (const double alpha : {1e-4, 1.42e-3, 3.5e-3, 0.1})
    for (const double k_m : {1e-18, 9.877e-16, 1e-13}) {
      const double s = cubic_law_tip_length(alpha, k_m);
      EXPECT_NEAR(alpha * alpha * alpha * s * s / 12.0, k_m, 1e-12 * k_m) << alpha << ", " << k_m;
    }
  EXPECT_NEAR(cubic_law_tip_length(1.42e-3, 9.877e-16), 2.035e-3, 0.005e-3);
  EXPECT_THROW(cubic_law_tip_length(0.0, 1e-15), std::invalid_argument);
  EXPECT_THROW(cubic_law_tip_length(1e-3, -1.0), std::invalid_argument);
}

// Across an element whose open fraction f lies in a layer across it: rock of k_m over (1 − f)
// of its width in series with water, 1/k = (1 − f)/k_m + f/∞, so k = k_m/(1 − f) exactly (the
// harmonic mean of layers in series); nothing open leaves k_m, a negative fraction (blocks
// overlapping by their penetration) too, and the open water is bounded by the cap.
TEST(OpenFraction, RockInSeriesWithOpenWaterAcrossTheElement) {
  const double k_m = 1e-19, cap = kDefaultFracturePermeabilityCap;
  EXPECT_EQ(permeability_across_open_fraction(k_m, 0.0, cap), k_m);
  EXPECT_EQ(permeability_across_open_fraction(k_m, -1e-6, cap), k_m);
  for (const double f : {1e-6, 0.25, 0.5, 0.9, 0.999})
    EXPECT_NEAR(permeability_across_open_fraction(k_m, f, cap), k_m / (1.0 - f), 1e-15 * k_m / (1.0 - f)) << f;
  EXPECT_EQ(permeability_across_open_fraction(k_m, 1.0, cap), cap);
  EXPECT_EQ(permeability_across_open_fraction(k_m, 1.0 - 1e-16, cap), cap);
  EXPECT_EQ(permeability_across_open_fraction(1e-5, 0.5, cap), 1e-5);  // a k_m over the cap stays
}

}  // namespace
}  // namespace hydrodda::hydro
