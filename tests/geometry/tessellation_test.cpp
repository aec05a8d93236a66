// Tessellation of a convex polygon into sub-blocks (geometry/tessellation.hpp): exact
// identities of a partition. The sub-blocks' areas sum to the polygon's (to 1e-12 of it:
// round-off of the clipping; the welding of vertices within 1e-2 size moves no vertex of a
// face that stays, only ends of faces shorter than that); every face names its neighbour and
// is named back, along the same segment (to 1e-9 m); each Voronoi cell holds its seed and
// no other seed is nearer any of its vertices (to 2e-2 size: the welding moves a vertex by up to 1e-2 size).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/polygon.hpp"
#include "geometry/tessellation.hpp"

namespace hydrodda::geometry {
namespace {

const Polygon kSquare{{0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}, {0.0, 3.0}};
constexpr double kSize = 0.5;

Tessellation tessellate(const Polygon& polygon, TessellationKind kind, std::uint64_t seed = 7) {
  const std::vector<Point> seeds = select_seeds(polygon, generate_seeds(bounding_box(polygon), kSize, seed), 0.2 * kSize);
  return tessellate_convex(polygon, seeds, kSize, kind);
}

void expect_partition(const Polygon& polygon, const Tessellation& t) {
  ASSERT_EQ(t.cells.size(), t.edge_sources.size());
  double total = 0.0;
  for (std::size_t c = 0; c < t.cells.size(); ++c) {
    const Polygon& cell = t.cells[c];
    ASSERT_EQ(cell.size(), t.edge_sources[c].size());
    EXPECT_GT(signed_area(cell), 0.0) << "sub-block " << c;
    total += signed_area(cell);
    for (std::size_t e = 0; e < cell.size(); ++e) {
      const int source = t.edge_sources[c][e];
      const Point a = cell[e];
      const Point b = cell[(e + 1) % cell.size()];
      if (source < 0) {
        // On the polygon's edge −1 − source.
        const std::size_t k = static_cast<std::size_t>(-1 - source);
        EXPECT_LT(distance_to_segment(a, polygon[k], polygon[(k + 1) % polygon.size()]), 1e-9);
        EXPECT_LT(distance_to_segment(b, polygon[k], polygon[(k + 1) % polygon.size()]), 1e-9);
        continue;
      }
      // The neighbour has the same face, run the other way.
      const Polygon& other = t.cells[static_cast<std::size_t>(source)];
      int back = -1;
      for (std::size_t f = 0; f < other.size(); ++f)
        if (t.edge_sources[static_cast<std::size_t>(source)][f] == static_cast<int>(c)) back = static_cast<int>(f);
      ASSERT_GE(back, 0) << "sub-block " << c << " edge " << e;
      EXPECT_LT(distance(a, other[(static_cast<std::size_t>(back) + 1) % other.size()]), 1e-9);
      EXPECT_LT(distance(b, other[static_cast<std::size_t>(back)]), 1e-9);
    }
  }
  EXPECT_NEAR(total, signed_area(polygon), 1e-12 * signed_area(polygon));
}

TEST(Tessellation, VoronoiCellsPartitionTheSquareAndShareTheirFaces) {
  const Tessellation t = tessellate(kSquare, TessellationKind::voronoi);
  // A jittered grid of 8 × 6 seeds less those within 0.1 m of the edges.
  EXPECT_GT(t.cells.size(), 30u);
  EXPECT_LE(t.cells.size(), 48u);
  expect_partition(kSquare, t);
}

TEST(Tessellation, VoronoiCellsHoldTheirSeedsAndAreNearestToThem) {
  const std::vector<Point> seeds = select_seeds(kSquare, generate_seeds(bounding_box(kSquare), kSize, 3), 0.2 * kSize);
  const Tessellation t = tessellate_convex(kSquare, seeds, kSize, TessellationKind::voronoi);
  ASSERT_EQ(t.cells.size(), seeds.size());
  for (std::size_t c = 0; c < seeds.size(); ++c) {
    EXPECT_TRUE(contains(t.cells[c], seeds[c]));
    for (Point v : t.cells[c])
      for (Point s : seeds) EXPECT_GE(distance(v, s), distance(v, seeds[c]) - 2e-2 * kSize);
  }
}

TEST(Tessellation, TrianglesPartitionTheSquareAndShareTheirFaces) {
  const Tessellation t = tessellate(kSquare, TessellationKind::triangles);
  for (const Polygon& cell : t.cells) EXPECT_EQ(cell.size(), 3u);
  expect_partition(kSquare, t);
}

TEST(Tessellation, AConvexPolygonOfAnyShapeIsPartitioned) {
  const Polygon hexagon{{0.0, 0.0}, {3.0, -1.0}, {5.0, 1.0}, {4.5, 3.0}, {1.0, 3.5}, {-1.0, 2.0}};
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    expect_partition(hexagon, tessellate(hexagon, TessellationKind::voronoi, seed));
    expect_partition(hexagon, tessellate(hexagon, TessellationKind::triangles, seed));
  }
}

// Two seeds whose bisector, y = x − 3e-3 (at 45°), crosses the square's bottom 3e-3 m from its
// corner (0, 0), within the welding's 1e-2 size = 5e-3 m of it, the crossing coming first in
// the cells' order: the corner stays where it is and the crossing goes onto it, so that the
// cells still fill the square (its corners on their edges to 1e-9 m, the areas summing to it
// to 1e-12). Welded the other way, the upper cell's left edge ran from (3e-3, 0) and the cells
// missed a sliver of 4.5e-3 m² of the square.
TEST(Tessellation, AWeldNearAPolygonsCornerKeepsTheCorner) {
  const Point middle{1.5015, 1.4985};  // on the bisector
  const Point across{0.3, -0.3};       // along its normal
  const std::vector<Point> seeds{middle + across, middle - across};
  const Tessellation t = tessellate_convex(kSquare, seeds, kSize, TessellationKind::voronoi);
  ASSERT_EQ(t.cells.size(), 2u);
  expect_partition(kSquare, t);
  for (const Polygon& cell : t.cells)
    for (Point v : cell) EXPECT_TRUE(v.y > 0.0 || v.x == 0.0 || v.x == 4.0) << "a vertex at (" << v.x << ", " << v.y << ")";
}

TEST(Tessellation, TheSameSeedGivesTheSameSubBlocks) {
  const Tessellation a = tessellate(kSquare, TessellationKind::voronoi, 11);
  const Tessellation b = tessellate(kSquare, TessellationKind::voronoi, 11);
  ASSERT_EQ(a.cells.size(), b.cells.size());
  for (std::size_t c = 0; c < a.cells.size(); ++c) EXPECT_EQ(a.cells[c], b.cells[c]);
}

TEST(Tessellation, ANonConvexPolygonIsRefused) {
  const Polygon notch{{0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}, {2.0, 1.0}, {0.0, 3.0}};
  EXPECT_THROW(tessellate_convex(notch, std::vector<Point>{{1.0, 0.5}, {3.0, 0.5}}, kSize, TessellationKind::voronoi),
               std::invalid_argument);
}

// A crack's seeds (make_crack_seeds): with the grid's seeds near it left out, the sub-blocks'
// faces along the crack's line cover it exactly, from its start to its end (the bisectors of
// the mirrored pairs: to 1e-9 m), with a face ending at each of its ends, and the whole is a
// partition; on both kinds of sub-blocks.
TEST(Tessellation, ACracksSeedsMakeFacesAlongItEndingAtItsEnds) {
  const Segment2 crack{{1.0, 1.3}, {2.9, 1.7}};
  const double length = distance(crack.from, crack.to);
  for (const TessellationKind kind : {TessellationKind::voronoi, TessellationKind::triangles}) {
    std::vector<Point> seeds;
    for (Point p : select_seeds(kSquare, generate_seeds(bounding_box(kSquare), kSize, 7), 0.2 * kSize))
      if (!lies_near_crack(p, crack, kSize)) seeds.push_back(p);
    const CrackSeeds pairs = make_crack_seeds(crack, 0.25);
    EXPECT_NEAR(pairs.spacing, length / std::round(length / 0.25), 1e-15);
    for (Point p : select_seeds(kSquare, pairs.seeds, 0.2 * kSize)) seeds.push_back(p);
    const Tessellation t = tessellate_convex(kSquare, seeds, pairs.spacing, kind);
    expect_partition(kSquare, t);
    double on_crack = 0.0;  // each face once: from the lower-numbered cell
    bool starts = false, ends = false;
    for (std::size_t c = 0; c < t.cells.size(); ++c)
      for (std::size_t e = 0; e < t.cells[c].size(); ++e) {
        const Point a = t.cells[c][e], b = t.cells[c][(e + 1) % t.cells[c].size()];
        if (t.edge_sources[c][e] <= static_cast<int>(c) || !lies_on_crack(a, b, crack, 1e-9)) continue;
        on_crack += distance(a, b);
        starts = starts || distance(a, crack.from) < 1e-9 || distance(b, crack.from) < 1e-9;
        ends = ends || distance(a, crack.to) < 1e-9 || distance(b, crack.to) < 1e-9;
      }
    EXPECT_NEAR(on_crack, length, 1e-9) << static_cast<int>(kind);
    EXPECT_TRUE(starts && ends) << static_cast<int>(kind);
  }
}

}  // namespace
}  // namespace hydrodda::geometry
