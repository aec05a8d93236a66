// Triangle ∩ polygon areas against Boost.Geometry (the oracle), over random convex and
// non-convex polygons, and exact cases.

#define BOOST_GEOMETRY_NO_ROBUSTNESS  // plain floating point, as our kernel: see DESIGN.md §5
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "geometry/clipping.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::geometry {
namespace {

namespace bg = boost::geometry;
using BoostPoint = bg::model::d2::point_xy<double>;
using BoostPolygon = bg::model::polygon<BoostPoint, false>;  // counter-clockwise
using BoostMulti = bg::model::multi_polygon<BoostPolygon>;

BoostPolygon to_boost(std::span<const Point> polygon) {
  BoostPolygon out;
  for (Point p : polygon) bg::append(out.outer(), BoostPoint(p.x, p.y));
  bg::correct(out);
  return out;
}

double oracle_area(const std::array<Point, 3>& t, std::span<const Point> polygon) {
  BoostMulti result;
  bg::intersection(to_boost(t), to_boost(polygon), result);
  return bg::area(result);
}

// A star-shaped polygon (non-convex when the radii vary), counter-clockwise.
Polygon random_star(std::mt19937_64& rng, Point centre, double radius, int n, double spread) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * (i + 0.8 * unit(rng)) / n;
    const double r = radius * (1.0 - spread * unit(rng));
    p.push_back({centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)});
  }
  return p;
}

TEST(ClippedArea, ExactCases) {
  const Polygon square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // Triangle inside: its own area; outside: 0; half over an edge: half.
  EXPECT_DOUBLE_EQ(clipped_area({Point{0.1, 0.1}, Point{0.5, 0.1}, Point{0.1, 0.5}}, square), 0.08);
  EXPECT_EQ(clipped_area({Point{2, 0}, Point{3, 0}, Point{2, 1}}, square), 0.0);
  EXPECT_DOUBLE_EQ(clipped_area({Point{0.5, 0}, Point{1.5, 0}, Point{0.5, 1}}, square), 0.375);
  // Touching along an edge only: no area. Clockwise triangle: same as counter-clockwise.
  EXPECT_EQ(clipped_area({Point{1, 0}, Point{2, 0}, Point{1, 1}}, square), 0.0);
  EXPECT_DOUBLE_EQ(clipped_area({Point{0.1, 0.1}, Point{0.1, 0.5}, Point{0.5, 0.1}}, square), 0.08);
  // The triangle covers the square entirely.
  EXPECT_DOUBLE_EQ(clipped_area({Point{-1, -1}, Point{5, -1}, Point{-1, 5}}, square), 1.0);
}

TEST(ClippedArea, AgreesWithBoostGeometryOnRandomPairs) {
  // 1e5 random triangle–polygon pairs: convex (spread 0) and non-convex stars, overlapping
  // partly, wholly or not at all. Rounding in either code is of order ε L², L the triangle's
  // longest edge, so the error is measured against L²: at most 1e-12 for every triangle. For
  // well-shaped triangles (area ≥ 0.1 L², so L² and the area agree within a factor of 10),
  // the error is also at most 1e-12 of the triangle's own area. Slivers are kept in the first
  // measure: their area is far below L² and says nothing of the kernel's accuracy.
  std::mt19937_64 rng(20061);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::uniform_int_distribution<int> sides(3, 12);
  double worst_scaled = 0.0;
  double worst_relative = 0.0;
  int well_shaped = 0;
  for (int i = 0; i < 100000; ++i) {
    const std::array<Point, 3> t{Point{coord(rng), coord(rng)}, Point{coord(rng), coord(rng)},
                                 Point{coord(rng), coord(rng)}};
    const double spread = (i % 2 == 0) ? 0.0 : 0.7;
    const Polygon poly = random_star(rng, {coord(rng), coord(rng)}, 0.6, sides(rng), spread);
    const double longest = std::max({distance(t[0], t[1]), distance(t[1], t[2]), distance(t[2], t[0])});
    const double error = std::abs(clipped_area(t, poly) - oracle_area(t, poly));
    worst_scaled = std::max(worst_scaled, error / (longest * longest));
    const double ta = area(t);
    if (ta >= 0.1 * longest * longest) {
      ++well_shaped;
      worst_relative = std::max(worst_relative, error / ta);
    }
  }
  EXPECT_LE(worst_scaled, 1e-12);
  EXPECT_LE(worst_relative, 1e-12);
  EXPECT_GT(well_shaped, 30000);  // the second measure covers a large share of the pairs
}

TEST(ClippedArea, TouchingAndSharedVertexCases) {
  // Blocks of a regular grid touching a triangle at vertices and along edges: the pieces of
  // the triangle add up to its area (1e-12 relative).
  const std::array<Point, 3> t{Point{0.0, 0.0}, Point{2.0, 0.0}, Point{0.0, 2.0}};
  double sum = 0.0;
  for (int i = -1; i < 3; ++i)
    for (int j = -1; j < 3; ++j) {
      const Polygon cell{{1.0 * i, 1.0 * j}, {1.0 * i + 1, 1.0 * j}, {1.0 * i + 1, 1.0 * j + 1}, {1.0 * i, 1.0 * j + 1}};
      const double a = clipped_area(t, cell);
      EXPECT_NEAR(a, oracle_area(t, cell), 1e-12);
      sum += a;
    }
  EXPECT_NEAR(sum, 2.0, 2.0 * 1e-12);
}

}  // namespace
}  // namespace hydrodda::geometry
