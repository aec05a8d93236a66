// The divergence rule of the staggered loop: passes in a row whose change grew (from the third
// pass: the first change is 1 by definition), and by how much since the streak began.

#include <gtest/gtest.h>

#include <vector>

#include "coupling/staggered_loop.hpp"

namespace hydrodda::coupling {
namespace {

ChangeGrowth track(const std::vector<double>& changes, int ramp_passes = 1) {
  ChangeGrowth growth;
  for (std::size_t k = 0; k < changes.size(); ++k) growth.add(changes[k], static_cast<int>(k) + 1, ramp_passes);
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

// A load ramped over 5 passes (coupling.ramp_passes) moves the blocks more each pass while it
// rises: those changes, doubling from pass 2 to pass 6, are no divergence. Pass 5 is the first
// at the full load, so the change of pass 6 is the first between two such passes, and growth
// counts from pass 7, which compares it with pass 6's. Without the ramp the same history
// diverges; with it, growth that goes on after the ramp does.
TEST(Divergence, ChangesThatGrowWithARampedLoadAreNoDivergence) {
  const std::vector<double> ramped{1.0, 1e-3, 2e-3, 4e-3, 8e-3, 1.6e-2, 3.2e-2};
  EXPECT_EQ(track(ramped, 5).passes, 1);
  EXPECT_FALSE(track(ramped, 5).diverging(5, 10.0));
  EXPECT_TRUE(track(ramped, 1).diverging(5, 10.0));
  std::vector<double> growing_after = ramped;
  for (double c : {6.4e-2, 1.28e-1, 2.56e-1, 5.12e-1}) growing_after.push_back(c);
  const ChangeGrowth after = track(growing_after, 5);
  EXPECT_EQ(after.passes, 5);
  EXPECT_EQ(after.base, 1.6e-2);
  EXPECT_TRUE(after.diverging(5, 10.0));
}

// A loading path (the breach command) takes each load from the state the last one held, and a
// state held unsettled may end on a long streak of growing changes: a user's faulted, bonded
// seal held at 1,687.5 m after 23 passes of growth, and its next load, 1,706.25 m, was told
// "the coupling loop diverges (24 passes of growing change)" after a single pass. A new load
// restarts the count: its first pass's change is the step to the new load, not growth, and
// growth under the new load counts from the pass after it.
TEST(Divergence, ANewLoadCountsGrowthAfresh) {
  ChangeGrowth growth = track({1.0, 1e-3, 2e-3, 4e-3, 8e-3, 1.6e-2, 3.2e-2});
  ASSERT_TRUE(growth.diverging(5, 10.0));
  growth.restart();
  growth.add(0.5, 8);  // the step to the new load
  EXPECT_EQ(growth.passes, 0);
  EXPECT_FALSE(growth.diverging(5, 10.0));
  for (int k = 9; k <= 12; ++k) growth.add(1e-3 * (k - 8), k);  // falls, then grows three passes
  EXPECT_EQ(growth.passes, 3);
  EXPECT_FALSE(growth.diverging(3, 10.0));  // 4e-3 is 4 times the 1e-3 the streak began from
  for (int k = 13; k <= 14; ++k) growth.add(1e-2 * (k - 12), k);
  EXPECT_EQ(growth.passes, 5);
  EXPECT_EQ(growth.base, 1e-3);
  EXPECT_TRUE(growth.diverging(5, 10.0));  // 2e-2, 20 times
}

}  // namespace
}  // namespace hydrodda::coupling
