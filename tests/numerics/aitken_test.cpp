#include "numerics/aitken.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace hydrodda::numerics {
namespace {

TEST(Aitken, UpdatesThatFlipSignHalveTheRelaxation) {
  const std::vector<double> previous{1.0, -2.0, 0.5}, update{-1.0, 2.0, -0.5};
  // r_k = −r_{k−1}: ω_k = −ω (r·(−2 r)) / (4 |r|²) = ω / 2.
  EXPECT_DOUBLE_EQ(aitken_relaxation(1.0, previous, update), 0.5);
  EXPECT_DOUBLE_EQ(aitken_relaxation(0.6, previous, update), 0.3);
}

TEST(Aitken, ALinearContractionGetsItsSecantStep) {
  // Updates that shrink by a factor q along one direction: r_k = q r_{k−1}. The secant step
  // ω_k = ω / (1 − q) lands on the fixed point; clipped to 1 where it would go past.
  const std::vector<double> previous{2.0, 4.0};
  const std::vector<double> grown{3.0, 6.0}, shrunk{1.0, 2.0};
  EXPECT_DOUBLE_EQ(aitken_relaxation(0.2, previous, shrunk), 0.4);  // q = 1/2
  EXPECT_DOUBLE_EQ(aitken_relaxation(0.2, previous, grown), kMinAitkenRelaxation);  // q = 3/2: ω < 0
  EXPECT_DOUBLE_EQ(aitken_relaxation(0.9, previous, shrunk), 1.0);
}

TEST(Aitken, TheSameUpdateTwiceKeepsTheRelaxation) {
  const std::vector<double> update{1.0, 2.0};
  EXPECT_EQ(aitken_relaxation(0.37, update, update), 0.37);
  EXPECT_THROW(aitken_relaxation(0.5, update, std::vector<double>{1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::numerics
