// Growing the step's arrays: an array overwritten in full grows by a quarter more than it
// needs and, grown again within that room, stays where it is (no fresh pages, no copy);
// reserving room keeps the values.

#include "dda/array_growth.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace hydrodda::dda {
namespace {

TEST(ArrayGrowth, ResizeForOverwriteGrowsWithHeadroom) {
  std::vector<double> v;
  resize_for_overwrite(v, 100000);
  EXPECT_EQ(v.size(), 100000u);
  EXPECT_GE(v.capacity(), 125000u);
  const double* before = v.data();
  resize_for_overwrite(v, 120000);
  EXPECT_EQ(v.size(), 120000u);
  EXPECT_EQ(v.data(), before);
  resize_for_overwrite(v, 200000);
  EXPECT_GE(v.capacity(), 250000u);
  std::vector<int> kept{1, 2, 3};
  reserve_with_headroom(kept, 8);
  EXPECT_GE(kept.capacity(), 10u);
  EXPECT_EQ(kept, (std::vector<int>{1, 2, 3}));  // reserving keeps the values
}

}  // namespace
}  // namespace hydrodda::dda
