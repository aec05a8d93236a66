// The load ramp's formula (coupling/load_ramp.hpp): pass k of n at r_k = min(1, k / n), the
// whole load F_k = r_k F, the overpressure's F_k = F_s + r_k (F − F_s), exact to rounding.

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "coupling/load_ramp.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Point;

TEST(LoadRamp, PassKOfNIsAtKOverNAndHeldAtOneAfter) {
  EXPECT_DOUBLE_EQ(ramp_factor(1, 3), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(ramp_factor(2, 3), 2.0 / 3.0);
  EXPECT_EQ(ramp_factor(3, 3), 1.0);
  EXPECT_EQ(ramp_factor(7, 3), 1.0);
  EXPECT_EQ(ramp_factor(1, 1), 1.0);
}

TEST(LoadRamp, TheWholeLoadIsScaledAndTheOverpressureRisesFromStillWater) {
  const std::vector<std::vector<Point>> full{{{3.0, -6.0}, {0.5, 9.0}}, {{-1.0, 2.0}}};
  const std::vector<std::vector<Point>> still{{{1.0, -2.0}, {0.5, 3.0}}, {{-4.0, 5.0}}};
  for (const double r : {0.25, 0.5, 0.75}) {
    std::vector<std::vector<Point>> whole = full, over = full;
    ramp_fluid_forces(whole, {}, r);
    ramp_fluid_forces(over, still, r);
    for (std::size_t b = 0; b < full.size(); ++b)
      for (std::size_t v = 0; v < full[b].size(); ++v) {
        EXPECT_DOUBLE_EQ(whole[b][v].x, r * full[b][v].x);
        EXPECT_DOUBLE_EQ(whole[b][v].y, r * full[b][v].y);
        EXPECT_DOUBLE_EQ(over[b][v].x, still[b][v].x + r * (full[b][v].x - still[b][v].x));
        EXPECT_DOUBLE_EQ(over[b][v].y, still[b][v].y + r * (full[b][v].y - still[b][v].y));
      }
  }
  // At r = 1 both are the full load, bit for bit.
  std::vector<std::vector<Point>> at_one = full;
  ramp_fluid_forces(at_one, still, 1.0);
  EXPECT_EQ(at_one[0][1].y, full[0][1].y);
  // Where the still water loads nothing (the overpressure convention), the two ramps agree bit
  // for bit: the overpressure ramp is the whole one.
  const std::vector<std::vector<Point>> none{{{0.0, 0.0}, {0.0, 0.0}}, {{0.0, 0.0}}};
  std::vector<std::vector<Point>> whole = full, over = full;
  ramp_fluid_forces(whole, {}, 1.0 / 3.0);
  ramp_fluid_forces(over, none, 1.0 / 3.0);
  for (std::size_t b = 0; b < full.size(); ++b)
    for (std::size_t v = 0; v < full[b].size(); ++v) {
      EXPECT_EQ(over[b][v].x, whole[b][v].x);
      EXPECT_EQ(over[b][v].y, whole[b][v].y);
    }
}

TEST(LoadRamp, StillWaterOfAnotherShapeIsRefused) {
  std::vector<std::vector<Point>> forces{{{1.0, 1.0}}};
  EXPECT_THROW(ramp_fluid_forces(forces, {{{1.0, 1.0}, {0.0, 0.0}}}, 0.5), std::invalid_argument);
  EXPECT_THROW(ramp_fluid_forces(forces, {{{1.0, 1.0}}, {{0.0, 0.0}}}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::coupling
