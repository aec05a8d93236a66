// The divergence rule of the staggered loop: passes in a row whose change grew (from the third
// pass: the first change is 1 by definition), and by how much since the streak began.

#include <gtest/gtest.h>

#include <vector>

#include "coupling/staggered_loop.hpp"

namespace hydrodda::coupling {
namespace {

ChangeGrowth track(const std::vector<double>& changes) {
  ChangeGrowth growth;
  for (std::size_t k = 0; k < changes.size(); ++k) growth.add(changes[k], static_cast<int>(k) + 1);
  return growth;
}

TEST(Divergence, GrowingChangesAreCountedAndAShrinkRestartsTheCount) {
  EXPECT_EQ(track({1.0, 0.5, 0.25, 0.125}).passes, 0);            // converging
  EXPECT_EQ(track({1.0, 1e-3, 2e-3, 4e-3, 8e-3}).passes, 3);      // growing since pass 3
  EXPECT_EQ(track({1.0, 1e-3, 2e-3, 4e-3, 3e-3, 5e-3}).passes, 1);  // a shrink restarts it
  EXPECT_EQ(track({1.0, 2.0}).passes, 0);                          // pass 2 never counts
  EXPECT_EQ(track({1.0, 0.1, 0.1}).passes, 0);                     // equal is not growth
}

TEST(Divergence, FivePassesOfTenfoldGrowthDivergeAndASlowCreepDoesNot) {
  // Doubling from 1e-3: 5 growing passes to 3.2e-2, 32 times the 1e-3 before them.
  const ChangeGrowth doubling = track({1.0, 1e-3, 2e-3, 4e-3, 8e-3, 1.6e-2, 3.2e-2});
  EXPECT_EQ(doubling.passes, 5);
  EXPECT_EQ(doubling.base, 1e-3);
  EXPECT_TRUE(doubling.diverging(5, 10.0));
  EXPECT_FALSE(doubling.diverging(6, 10.0));
  EXPECT_FALSE(doubling.diverging(0, 10.0));  // 0: the rule is off
  // The six-block up-down run grows 9.1e-3 -> 1.9e-2 over 3 passes and then converges.
  const ChangeGrowth creep = track({1.0, 0.5, 9.14e-3, 1.82e-2, 1.92e-2, 1.93e-2, 1.95e-2, 1.96e-2});
  EXPECT_EQ(creep.passes, 5);
  EXPECT_FALSE(creep.diverging(5, 10.0));
}

}  // namespace
}  // namespace hydrodda::coupling
