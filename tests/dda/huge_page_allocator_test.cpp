// The large-array allocator: arrays of 256 KiB or more start on a 2 MiB boundary (where a
// huge page can hold them), smaller ones come from the ordinary allocator, and a vector on it
// keeps its values as it grows across the threshold. Whether the kernel grants huge pages is
// its own affair (it may keep them off), so it is not asserted.

#include "dda/huge_page_allocator.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace hydrodda::dda {
namespace {

TEST(HugePageAllocator, LargeArraysStartOnHugePageBoundaries) {
  std::vector<double, HugePageAllocator<double>> large(1 << 20, 1.5);  // 8 MiB
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % (std::size_t{2} << 20), 0u);
  std::vector<double, HugePageAllocator<double>> small(100, 2.5);
  EXPECT_EQ(small[99], 2.5);
  EXPECT_EQ(large[(1 << 20) - 1], 1.5);
}

TEST(HugePageAllocator, AGrowingVectorKeepsItsValues) {
  std::vector<long, HugePageAllocator<long>> v;
  for (long i = 0; i < 200000; ++i) v.push_back(3 * i + 1);  // 1.6 MB, past 256 KiB
  bool kept = true;
  for (long i = 0; i < 200000; ++i) kept = kept && v[i] == 3 * i + 1;
  EXPECT_TRUE(kept);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % (std::size_t{2} << 20), 0u);
}

// Grown past its capacity, an array overwritten in full gets a quarter more room; grown again
// within that room, it stays where it is (no fresh pages, no copy).
TEST(HugePageAllocator, ResizeForOverwriteGrowsWithHeadroom) {
  std::vector<double, HugePageAllocator<double>> v;
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
