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
  for (bool at_rest : {false, true, false, false, false}) trail.add(at_rest, true, {});
  EXPECT_EQ(trail.passes_not_at_rest(), 3);
  trail.add(true, false, {});  // at rest on a step cut short: not moving, not rested either
  EXPECT_EQ(trail.passes_not_at_rest(), 0);
  EXPECT_FALSE(trail.rested_in_last(1));
  EXPECT_EQ(trail.passes_cut_short(3), 1);
  EXPECT_EQ(trail.passes_cut_short(100), 1);
}

TEST(PassTrail, RestedInLastLooksOnlyAtTheLastPasses) {
  hb::PassTrail trail;
  trail.add(false, true, {});
  for (int i = 0; i < 4; ++i) trail.add(true, true, {});
  EXPECT_TRUE(trail.rested_in_last(4));
  EXPECT_FALSE(trail.rested_in_last(5));
  EXPECT_FALSE(trail.rested_in_last(10));  // all 5 passes, the first still moving
}

TEST(PassTrail, RangesEachRegionOverTheLastPasses) {
  // Two regions; the second has no value in one pass. Over the last 3 passes the first ranges
  // 966..1044 exactly (the values given), the second 2..2 from the passes that have one.
  hb::PassTrail trail;
  trail.add(true, true, {5000.0, 9.0});  // before the last 3: left out
  trail.add(true, true, {1044.0, std::nullopt});
  trail.add(true, true, {966.0, 2.0});
  trail.add(true, true, {1000.0, 2.0});
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
