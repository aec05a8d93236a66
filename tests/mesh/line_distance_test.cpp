// LineDistance: the indexed nearest-line distance of the mesh size field against the loop over
// every line it replaces. Under the reach the two are the same number, bit for bit (the index
// only skips lines farther than the reach, and measures the others as the loop does); at or
// beyond it, both are at least the reach, where refined_size() gives the coarse size anyway.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "geometry/polygon.hpp"
#include "mesh/line_distance.hpp"

namespace hydrodda::mesh {
namespace {

double nearest_by_loop(const std::vector<Segment>& lines, geometry::Point p) {
  double d = INFINITY;
  for (const Segment& s : lines) d = std::min(d, geometry::distance_to_segment(p, s.from, s.to));
  return d;
}

TEST(LineDistance, IsTheLoopOverEveryLineWithinTheReach) {
  // A 100 m × 20 m seal: 300 short joints, 20 beds across the whole width, 10 long oblique
  // traces (whose boxes cover much of the domain), and a segment of zero length.
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> x(0.0, 100.0), y(0.0, 20.0), unit(-1.0, 1.0);
  std::vector<Segment> lines;
  for (int i = 0; i < 300; ++i) {
    const geometry::Point a{x(random), y(random)};
    lines.push_back({a, {a.x + 0.1 * unit(random), a.y + 2.0 * unit(random)}});
  }
  for (int i = 0; i < 20; ++i) lines.push_back({{0.0, i + 0.5}, {100.0, i + 0.5 + 0.01 * unit(random)}});
  for (int i = 0; i < 10; ++i) lines.push_back({{x(random), 0.0}, {x(random), 20.0}});
  lines.push_back({{50.0, 10.0}, {50.0, 10.0}});
  for (double reach : {0.05, 0.3, 2.0}) {
    const LineDistance index(lines, reach);
    int within = 0;
    for (int i = 0; i < 20000; ++i) {
      const geometry::Point p{x(random) * 1.02 - 1.0, y(random) * 1.1 - 1.0};
      const double expected = nearest_by_loop(lines, p), got = index.nearest(p);
      if (expected < reach) {
        ++within;
        ASSERT_EQ(got, expected) << "reach " << reach << " at (" << p.x << ", " << p.y << ")";
      } else {
        ASSERT_GE(got, reach) << "reach " << reach << " at (" << p.x << ", " << p.y << ")";
      }
    }
    EXPECT_GT(within, 1000) << "reach " << reach;  // the test sees the refined zone, not only its outside
  }
}

TEST(LineDistance, NoLinesIsInfinitelyFar) {
  const LineDistance index(std::vector<Segment>{}, 1.0);
  EXPECT_EQ(index.nearest({0.0, 0.0}), INFINITY);
}

}  // namespace
}  // namespace hydrodda::mesh
