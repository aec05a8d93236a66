#include "geometry/polygon.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace hydrodda::geometry {
namespace {

// Unit square, counter-clockwise: area 1, centroid (0.5, 0.5), exact in binary.
const Polygon kSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

TEST(Polygon, SquareAreaAndCentroidAreExact) {
  EXPECT_EQ(signed_area(kSquare), 1.0);
  const Point c = centroid(kSquare);
  EXPECT_EQ(c.x, 0.5);
  EXPECT_EQ(c.y, 0.5);
}

TEST(Polygon, ClockwiseHasNegativeArea) {
  const Polygon cw{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  EXPECT_EQ(signed_area(cw), -1.0);
  EXPECT_EQ(area(cw), 1.0);
}

TEST(Polygon, RegularPolygonAreaFarFromOrigin) {
  // Regular n-gon of circumradius R: A = (n/2) R² sin(2π/n); shifted by 1e6 to test the
  // shoelace sum's cancellation. Tolerance 1e-12 relative.
  const int n = 64;
  const double r = 2.0;
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    p.push_back({1e6 + r * std::cos(t), -1e6 + r * std::sin(t)});
  }
  const double exact = 0.5 * n * r * r * std::sin(2.0 * std::numbers::pi / n);
  // Coordinates near 1e6 carry an absolute rounding of ~1e-10, so 1e-9 relative is the bound.
  EXPECT_NEAR(signed_area(p), exact, 1e-9 * exact);
  const Point c = centroid(p);
  EXPECT_NEAR(c.x, 1e6, 1e-9);
  EXPECT_NEAR(c.y, -1e6, 1e-9);
}

TEST(Polygon, LShapeCentroid) {
  // L of three unit squares: centroid = mean of the squares' centres = (2/3+... ) computed:
  // squares at (0.5,0.5), (1.5,0.5), (0.5,1.5) -> (5/6, 5/6).
  const Polygon l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(signed_area(l), 3.0);
  const Point c = centroid(l);
  EXPECT_NEAR(c.x, 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(c.y, 5.0 / 6.0, 1e-15);
}

TEST(Polygon, SelfIntersectionFound) {
  const Polygon bowtie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_TRUE(find_self_intersection(bowtie).has_value());
  EXPECT_FALSE(find_self_intersection(kSquare).has_value());
  const Polygon l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_FALSE(find_self_intersection(l).has_value());
  // A spike that folds back on itself along one line.
  const Polygon spike{{0, 0}, {2, 0}, {1, 0}, {1, 1}};
  EXPECT_TRUE(find_self_intersection(spike).has_value());
}

TEST(Polygon, ContainsAndDistance) {
  EXPECT_TRUE(contains(kSquare, {0.3, 0.7}));
  EXPECT_FALSE(contains(kSquare, {1.3, 0.7}));
  EXPECT_DOUBLE_EQ(distance_to_segment({0.5, 2.0}, {0, 1}, {1, 1}), 1.0);
  EXPECT_DOUBLE_EQ(distance_to_segment({3.0, 1.0}, {0, 1}, {1, 1}), 2.0);
}

// The width across a polygon's edges: min over edges of its extent along the edge's normal.
// Exact values: a rectangle's shorter side whatever its rotation, a 3-4-5 triangle's least
// altitude 3 × 4 / 5, a regular hexagon's width across flats √3 (side 1); 1e-12.
TEST(Polygon, WidthAcrossEdges) {
  const double c = std::cos(0.5), s = std::sin(0.5);
  Polygon strip;
  for (Point p : Polygon{{0, 0}, {3, 0}, {3, 0.2}, {0, 0.2}}) strip.push_back({c * p.x - s * p.y + 7, s * p.x + c * p.y - 2});
  EXPECT_NEAR(width_across_edges(strip), 0.2, 1e-12);
  EXPECT_NEAR(width_across_edges(Polygon{{0, 0}, {4, 0}, {0, 3}}), 2.4, 1e-12);
  Polygon hexagon;
  for (int k = 0; k < 6; ++k) hexagon.push_back({std::cos(k * std::numbers::pi / 3), std::sin(k * std::numbers::pi / 3)});
  EXPECT_NEAR(width_across_edges(hexagon), std::sqrt(3.0), 1e-12);
  // Not convex: across its own edges (all along the axes here) the L is 2 wide.
  EXPECT_NEAR(width_across_edges(Polygon{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}), 2.0, 1e-12);
  EXPECT_EQ(width_across_edges(Polygon{{0, 0}, {1, 0}}), 0.0);
}

TEST(Segments, IntersectionCases) {
  EXPECT_TRUE(segments_intersect({0, 0}, {1, 1}, {0, 1}, {1, 0}));
  EXPECT_FALSE(segments_intersect({0, 0}, {1, 0}, {0, 1}, {1, 1}));
  EXPECT_TRUE(segments_intersect({0, 0}, {1, 0}, {1, 0}, {2, 5}));  // touching at an end
  const auto t = line_intersection_parameter({0, 0}, {2, 0}, {0.5, -1}, {0.5, 1});
  ASSERT_TRUE(t.has_value());
  EXPECT_DOUBLE_EQ(*t, 0.25);
  EXPECT_FALSE(line_intersection_parameter({0, 0}, {1, 0}, {0, 1}, {1, 1}).has_value());
}

}  // namespace
}  // namespace hydrodda::geometry
