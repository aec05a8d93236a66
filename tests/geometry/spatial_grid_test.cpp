// SpatialGrid::for_each_overlap against a scan of every box: each overlapping item reported
// exactly once, none other, from queries inside, across and outside the grid, with boxes of
// every size from a point to the whole set (an item in many cells is reported once without
// any state kept between queries).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/polygon.hpp"
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

// SpatialGrid::nearest against the loop over every item: segments of every length, their
// distance from points inside, beside and far outside the grid; every fifth segment does not
// qualify (infinite distance), and a copy of one segment makes a tie that the lower id wins.
TEST(SpatialGrid, NearestIsTheLoopsNearestLowestIdOnATie) {
  std::mt19937_64 rng(7);
  std::vector<std::array<Point, 2>> segments;
  std::vector<Box> boxes;
  for (int i = 0; i < 400; ++i) {
    const Box b = random_box(rng, i % 50 == 0 ? 8.0 : 0.5);
    segments.push_back({b.lo, b.hi});
  }
  segments.push_back(segments[17]);  // the same segment twice: ids 17 and 400
  for (const auto& [a, b] : segments) {
    Box box;
    box.add(a);
    box.add(b);
    boxes.push_back(box);
  }
  const SpatialGrid grid(boxes);
  const auto distance = [&](Point p, int id) {
    return id % 5 == 4 ? INFINITY : distance_to_segment(p, segments[id][0], segments[id][1]);
  };
  std::uniform_real_distribution<double> where(-30.0, 40.0);
  for (int q = 0; q < 3000; ++q) {
    const Point p = q == 0 ? segments[17][0] : Point{where(rng), where(rng)};
    int expected = -1;
    double best = INFINITY;
    for (int id = 0; id < static_cast<int>(segments.size()); ++id)
      if (distance(p, id) < best) {
        best = distance(p, id);
        expected = id;
      }
    for (double first_reach : {0.01, 0.3, 5.0})
      ASSERT_EQ(grid.nearest(p, first_reach, [&](int id) { return distance(p, id); }), expected)
          << "at (" << p.x << ", " << p.y << "), first reach " << first_reach;
  }
  EXPECT_EQ(SpatialGrid(std::vector<Box>{}).nearest({0, 0}, 1.0, [](int) { return 0.0; }), -1);
}

}  // namespace
}  // namespace hydrodda::geometry
