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

}  // namespace
}  // namespace hydrodda::geometry
