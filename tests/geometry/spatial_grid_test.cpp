// SpatialGrid::for_each_overlap against a scan of every box: each overlapping item reported
// exactly once, none other, from queries inside, across and outside the grid, with boxes of
// every size from a point to the whole set (an item in many cells is reported once without
// any state kept between queries).

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "geometry/spatial_grid.hpp"

namespace hydrodda::geometry {
namespace {

Box random_box(std::mt19937_64& rng, double largest) {
  std::uniform_real_distribution<double> where(-1.0, 11.0), size(0.0, 1.0);
  const Point lo{where(rng), where(rng)};
  const double s = size(rng);
  return {lo, lo + Point{largest * s * s * s, largest * s * s}};  // mostly small, some large
}

TEST(SpatialGrid, ReportsEveryOverlappingItemOnce) {
  std::mt19937_64 rng(29);
  for (double items_per_cell : {0.5, 1.0, 4.0}) {
    std::vector<Box> boxes;
    for (int i = 0; i < 2000; ++i) boxes.push_back(random_box(rng, 6.0));
    boxes.push_back({{3.0, 3.0}, {3.0, 3.0}});  // a point
    const SpatialGrid grid(boxes, items_per_cell);
    for (int q = 0; q < 3000; ++q) {
      const Box query = random_box(rng, 14.0);
      std::vector<int> reported;
      grid.for_each_overlap(query, [&](int id) { reported.push_back(id); });
      std::vector<int> expected;
      for (int id = 0; id < static_cast<int>(boxes.size()); ++id)
        if (boxes[id].overlaps(query)) expected.push_back(id);
      std::sort(reported.begin(), reported.end());
      ASSERT_EQ(reported, expected) << "query " << q << ", " << items_per_cell << " items per cell";
    }
  }
}

}  // namespace
}  // namespace hydrodda::geometry
