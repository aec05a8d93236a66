// The record of a breach step's passes from which an unconverged step is judged (held,
// unsettled or still moving): exact identities on hand-made passes.

#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "breach/pass_trail.hpp"

namespace hb = hydrodda::breach;

TEST(PassTrail, CountsTheLastPassesInARowWhoseBlocksDidNotComeToRest) {
  hb::PassTrail trail;
  EXPECT_EQ(trail.passes_not_at_rest(), 0);
  EXPECT_FALSE(trail.rested_in_last(10));  // no pass: nothing came to rest
  for (bool at_rest : {false, true, false, false, false}) trail.add(at_rest, true, true, {});
  EXPECT_EQ(trail.passes_not_at_rest(), 3);
  trail.add(true, false, false, {});  // at rest on a step cut short: not moving, not rested either
  EXPECT_EQ(trail.passes_not_at_rest(), 0);
  EXPECT_FALSE(trail.rested_in_last(1));
  EXPECT_EQ(trail.passes_cut_short(3), 1);
  EXPECT_EQ(trail.passes_cut_short(100), 1);
}

TEST(PassTrail, APassCutShortThatStillMovedTheBlocksIsGettingThroughAndOneThatDidNotIsStalled) {
  hb::PassTrail trail;
  EXPECT_FALSE(trail.getting_through());  // no pass
  trail.add(false, false, true, {});  // cut short, moved past the tolerance
  EXPECT_TRUE(trail.getting_through());
  trail.add(false, false, false, {});  // cut short, barely moved: stalled
  EXPECT_FALSE(trail.getting_through());
  trail.add(false, true, true, {});  // moving at the full time step
  EXPECT_FALSE(trail.getting_through());
  trail.add(true, false, true, {});  // passed the at-rest test on a step cut short
  EXPECT_FALSE(trail.getting_through());
  EXPECT_EQ(trail.passes_not_at_rest(), 0);
}

TEST(PassTrail, RestedInLastLooksOnlyAtTheLastPasses) {
  hb::PassTrail trail;
  trail.add(false, true, true, {});
  for (int i = 0; i < 4; ++i) trail.add(true, true, false, {});
  EXPECT_TRUE(trail.rested_in_last(4));
  EXPECT_FALSE(trail.rested_in_last(5));
  EXPECT_FALSE(trail.rested_in_last(10));  // all 5 passes, the first still moving
}

TEST(PassTrail, RangesEachRegionOverTheLastPasses) {
  // Two regions; the second has no value in one pass. Over the last 3 passes the first ranges
  // 966..1044 exactly (the values given), the second 2..2 from the passes that have one.
  hb::PassTrail trail;
  trail.add(true, true, false, {5000.0, 9.0});  // before the last 3: left out
  trail.add(true, true, false, {1044.0, std::nullopt});
  trail.add(true, true, false, {966.0, 2.0});
  trail.add(true, true, false, {1000.0, 2.0});
  const std::vector<std::optional<hb::ValueRange>> ranges = trail.ranges_over_last(3);
  ASSERT_EQ(ranges.size(), 2u);
  ASSERT_TRUE(ranges[0] && ranges[1]);
  EXPECT_EQ(ranges[0]->least, 966.0);
  EXPECT_EQ(ranges[0]->largest, 1044.0);
  EXPECT_DOUBLE_EQ(ranges[0]->spread(), (1044.0 - 966.0) / 1044.0);
  EXPECT_EQ(ranges[1]->least, 2.0);
  EXPECT_EQ(ranges[1]->largest, 2.0);
  EXPECT_EQ(ranges[1]->spread(), 0.0);
  trail.clear();
  EXPECT_EQ(trail.passes(), 0);
  EXPECT_TRUE(trail.ranges_over_last(3).empty());
}
