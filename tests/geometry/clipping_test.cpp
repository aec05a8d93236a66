// Triangle ∩ polygon areas against Boost.Geometry (the oracle), over random convex and
// non-convex polygons, and exact cases; the convex kernel (a triangle clipped by a polygon's
// half-planes) against the oracle and against the general kernel.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "clip_oracle.hpp"
#include "geometry/clipping.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::geometry {
namespace {

using testing::oracle_area;

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

TEST(ClippedArea, PartCentroidAgreesWithBoostGeometry) {
  // clip_part: the same area as clipped_area, and the centroid of the intersection against
  // Boost.Geometry's (area-weighted over its polygons), within 1e-12 of L² / area (the
  // centroid's rounding is that of the first moment, ε L³, over the area) on 1e4 random pairs
  // with a part of at least 1% of the triangle.
  std::mt19937_64 rng(20062);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::uniform_int_distribution<int> sides(3, 12);
  int compared = 0;
  for (int i = 0; i < 10000; ++i) {
    const std::array<Point, 3> t{Point{coord(rng), coord(rng)}, Point{coord(rng), coord(rng)},
                                 Point{coord(rng), coord(rng)}};
    const Polygon poly = random_star(rng, {coord(rng), coord(rng)}, 0.6, sides(rng), (i % 2 == 0) ? 0.0 : 0.7);
    const ClippedPart part = clip_part(t, poly);
    EXPECT_EQ(part.area, clipped_area(t, poly));
    if (part.area < 0.01 * area(t)) continue;
    const Point oracle = testing::oracle_centroid(t, poly);
    const double longest = std::max({distance(t[0], t[1]), distance(t[1], t[2]), distance(t[2], t[0])});
    EXPECT_LE(distance(part.centroid, oracle), 1e-12 * longest * longest * longest / part.area) << "pair " << i;
    ++compared;
  }
  EXPECT_GT(compared, 2000);
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

// A random convex polygon: the star of n points at equal radius (spread 0), in either
// orientation.
Polygon random_convex(std::mt19937_64& rng, Point centre, double radius, int n, bool clockwise) {
  Polygon p = random_star(rng, centre, radius, n, 0.0);
  if (clockwise) std::reverse(p.begin(), p.end());
  return p;
}

std::vector<HalfPlane> half_planes(std::span<const Point> polygon) {
  std::vector<HalfPlane> out;
  EXPECT_TRUE(append_half_planes(polygon, out));
  return out;
}

TEST(ConvexClip, HalfPlanesOnlyOfConvexPolygons) {
  std::vector<HalfPlane> out;
  // Collinear vertices along an edge are convex; a reflex vertex is not; nor is a segment.
  EXPECT_TRUE(append_half_planes(Polygon{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}, out));
  EXPECT_EQ(out.size(), 5u);
  EXPECT_FALSE(append_half_planes(Polygon{{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}, out));
  EXPECT_FALSE(append_half_planes(Polygon{{0, 0}, {1, 0}}, out));
  EXPECT_FALSE(append_half_planes(Polygon{{0, 0}, {1, 0}, {2, 0}}, out));
  EXPECT_EQ(out.size(), 5u);  // nothing appended by the refusals
  // Inward normals in either orientation: the centre is inside every half-plane.
  for (bool clockwise : {false, true}) {
    Polygon square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    if (clockwise) std::reverse(square.begin(), square.end());
    for (const HalfPlane& h : half_planes(square)) EXPECT_GT(h.distance({0.5, 0.5}), 0.0);
  }
}

TEST(ConvexClip, ExactCases) {
  const Polygon square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto edges = half_planes(square);
  // Wholly inside: the caller's area itself, bit for bit; outside: 0; touching an edge: 0.
  const std::array<Point, 3> inside{Point{0.1, 0.1}, Point{0.5, 0.1}, Point{0.1, 0.5}};
  EXPECT_EQ(clipped_area(inside, 0.0800000000000001, edges), 0.0800000000000001);
  EXPECT_TRUE(contains_triangle(edges, inside));
  EXPECT_EQ(clipped_area({Point{2, 0}, Point{3, 0}, Point{2, 1}}, 0.5, edges), 0.0);
  EXPECT_EQ(clipped_area({Point{1, 0}, Point{2, 0}, Point{1, 1}}, 0.5, edges), 0.0);
  // One edge cuts: one corner out (the triangle (0.5, 0), (1.5, 0), (0.5, 1) loses the corner
  // past x = 1, a quarter of its area) and two corners out (of (0.5, 0.2), (1.5, 0.2),
  // (1.5, 0.6), area 0.2, the corner at (0.5, 0.2) is kept, a quarter). Two edges cut: of
  // (0.5, 0.5), (1.5, 0.5), (0.5, 1.5) the square [0.5, 1]² is left.
  EXPECT_DOUBLE_EQ(clipped_area({Point{0.5, 0}, Point{1.5, 0}, Point{0.5, 1}}, 0.5, edges), 0.375);
  EXPECT_DOUBLE_EQ(clipped_area({Point{0.5, 0.2}, Point{1.5, 0.2}, Point{1.5, 0.6}}, 0.2, edges), 0.05);
  EXPECT_DOUBLE_EQ(clipped_area({Point{0.5, 0.5}, Point{1.5, 0.5}, Point{0.5, 1.5}}, 0.5, edges), 0.25);
  EXPECT_FALSE(contains_triangle(edges, {Point{0.5, 0}, Point{1.5, 0}, Point{0.5, 1}}));
  // The square inside a large triangle: every edge cuts.
  EXPECT_DOUBLE_EQ(clipped_area({Point{-1, -1}, Point{5, -1}, Point{-1, 5}}, 18.0, edges), 1.0);
}

TEST(ConvexClip, AgreesWithBoostGeometryAndTheGeneralKernel) {
  // 1e5 random pairs, as for the general kernel: a triangle and a convex polygon of 3–12
  // sides in either orientation, overlapping partly, wholly or not at all; the same bounds
  // (1e-12 of L² for every triangle, of the area for well-shaped ones). Far from the origin
  // too (offset 100, the size of a model in metres), where rounding grows with the
  // coordinates: there against 1e-12 · (L² + L · 100).
  std::mt19937_64 rng(20062);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::uniform_int_distribution<int> sides(3, 12);
  for (double offset : {0.0, 100.0}) {
    double worst_scaled = 0.0, worst_relative = 0.0, worst_general = 0.0;
    int cut = 0;
    for (int i = 0; i < 100000; ++i) {
      const Point o{offset, offset};
      const std::array<Point, 3> t{o + Point{coord(rng), coord(rng)}, o + Point{coord(rng), coord(rng)},
                                   o + Point{coord(rng), coord(rng)}};
      const Polygon poly = random_convex(rng, o + Point{coord(rng), coord(rng)}, 0.6, sides(rng), i % 2 == 1);
      const double ta = area(t);
      const double longest = std::max({distance(t[0], t[1]), distance(t[1], t[2]), distance(t[2], t[0])});
      const double scale = longest * longest + longest * offset;
      const double a = clipped_area(t, ta, half_planes(poly));
      const double error = std::abs(a - oracle_area(t, poly));
      worst_scaled = std::max(worst_scaled, error / scale);
      if (ta >= 0.1 * longest * longest) worst_relative = std::max(worst_relative, error / (ta + longest * offset));
      worst_general = std::max(worst_general, std::abs(a - clipped_area(t, poly)) / scale);
      cut += a > 0.0 && a < ta;
    }
    EXPECT_LE(worst_scaled, 1e-12) << "offset " << offset;
    EXPECT_LE(worst_relative, 1e-12) << "offset " << offset;
    EXPECT_LE(worst_general, 1e-12) << "offset " << offset;
    EXPECT_GT(cut, 20000) << "offset " << offset;  // many pairs are partial overlaps
  }
}

TEST(ConvexClip, PartHasTheAreaBitForBitAndTheGeneralKernelsCentroid) {
  // clip_part over half-planes: exactly clipped_area's area (the porosity with and without the
  // pieces is the same field), and the centroid of the general clip_part (itself checked
  // against Boost.Geometry above) within 1e-12 of L³ / area, on 1e5 random triangle–convex
  // pairs covering the closed-form one-edge cut (either corner case), several edges and a
  // triangle wholly inside (its own centroid).
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  std::uniform_int_distribution<int> sides(3, 12);
  int compared = 0, whole = 0;
  for (int i = 0; i < 100000; ++i) {
    const std::array<Point, 3> t{Point{coord(rng), coord(rng)}, Point{coord(rng), coord(rng)},
                                 Point{coord(rng), coord(rng)}};
    const Polygon poly = random_convex(rng, {coord(rng), coord(rng)}, 0.6 + (i % 4 == 0 ? 1.5 : 0.0), sides(rng),
                                       i % 2 == 1);
    const double ta = area(t);
    const auto edges = half_planes(poly);
    const ClippedPart part = clip_part(t, ta, edges);
    ASSERT_EQ(part.area, clipped_area(t, ta, edges)) << "pair " << i;
    if (part.area < 0.01 * ta) continue;
    whole += part.area == ta;
    const double longest = std::max({distance(t[0], t[1]), distance(t[1], t[2]), distance(t[2], t[0])});
    EXPECT_LE(distance(part.centroid, clip_part(t, poly).centroid), 1e-12 * longest * longest * longest / part.area)
        << "pair " << i;
    ++compared;
  }
  EXPECT_GT(compared, 20000);
  EXPECT_GT(whole, 1000);
}

TEST(ConvexClip, PiecesOfATriangleAddUpToItsArea) {
  // Area conservation: a triangle cut by a fan of convex pieces that tile a large square
  // (random lines through a grid) loses nothing: Σ pieces = its area to 1e-13 relative.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  // A 4 × 4 grid of quadrilaterals with jittered interior nodes over [−2, 2]²: convex for
  // jitters under a quarter of the spacing.
  std::array<std::array<Point, 5>, 5> node;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      const bool interior = i > 0 && i < 4 && j > 0 && j < 4;
      node[j][i] = {-2.0 + i + (interior ? jitter(rng) : 0.0), -2.0 + j + (interior ? jitter(rng) : 0.0)};
    }
  std::vector<Polygon> pieces;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) pieces.push_back({node[j][i], node[j][i + 1], node[j + 1][i + 1], node[j + 1][i]});
  const ClipPolygons prepared(pieces);
  std::uniform_real_distribution<double> coord(-1.9, 1.9);
  for (int k = 0; k < 1000; ++k) {
    const std::array<Point, 3> t{Point{coord(rng), coord(rng)}, Point{coord(rng), coord(rng)},
                                 Point{coord(rng), coord(rng)}};
    const double ta = area(t);
    double sum = 0.0;
    for (int p = 0; p < prepared.size(); ++p) sum += prepared.covered_area(p, t, ta);
    ASSERT_NEAR(sum, ta, 1e-13 * std::max(ta, 1.0)) << "triangle " << k;
  }
}

TEST(ConvexClip, PreparedPolygonsTakeTheGeneralKernelWhenNotConvex) {
  // An L-shaped (non-convex) block beside a square: covered_area is the general kernel's for
  // the first, the convex kernel's for the second; `holds` only ever for a convex polygon.
  const std::vector<Polygon> blocks{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {{3, 0}, {4, 0}, {4, 1}, {3, 1}}};
  const ClipPolygons prepared(blocks);
  const std::array<Point, 3> in_l{Point{0.1, 0.1}, Point{0.9, 0.1}, Point{0.1, 0.9}};
  const std::array<Point, 3> across{Point{0.5, 0.5}, Point{3.5, 0.5}, Point{0.5, 1.5}};
  EXPECT_FALSE(prepared.holds(0, in_l));
  EXPECT_EQ(prepared.covered_area(0, in_l, area(in_l)), clipped_area(in_l, blocks[0]));
  EXPECT_NEAR(prepared.covered_area(0, across, area(across)), oracle_area(across, blocks[0]), 1e-12);
  EXPECT_NEAR(prepared.covered_area(1, across, area(across)), oracle_area(across, blocks[1]), 1e-12);
  EXPECT_TRUE(prepared.holds(1, {Point{3.1, 0.1}, Point{3.9, 0.1}, Point{3.1, 0.9}}));
}

}  // namespace
}  // namespace hydrodda::geometry
