// Convex pieces of a simple polygon (geometry/convex_decomposition.hpp), Hertel & Mehlhorn
// (1983): the pieces are convex and counter-clockwise, their areas sum to the polygon's (to
// 1e-12 of it: a partition along diagonals, round-off only), each uses the polygon's vertices,
// and every edge of a piece is an edge of the polygon or a diagonal shared, run the other way,
// with exactly one other piece. Hertel & Mehlhorn's bound: at most 4 times the fewest pieces
// (for r reflex corners the fewest is at least ⌈r/2⌉ + 1; an L needs 2).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "geometry/convex_decomposition.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::geometry {
namespace {

std::vector<Point> points_of(const Polygon& polygon, const std::vector<int>& piece) {
  std::vector<Point> out;
  for (int i : piece) out.push_back(polygon[static_cast<std::size_t>(i)]);
  return out;
}

void expect_pieces(const Polygon& polygon, const std::vector<std::vector<int>>& pieces) {
  const int n = static_cast<int>(polygon.size());
  double total = 0.0;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const std::vector<Point> points = points_of(polygon, pieces[p]);
    total += signed_area(points);
    const std::size_t m = points.size();
    for (std::size_t k = 0; k < m; ++k)
      EXPECT_GE(orient(points[k], points[(k + 1) % m], points[(k + 2) % m]), 0.0) << "piece " << p;
    for (std::size_t k = 0; k < m; ++k) {
      const int a = pieces[p][k], b = pieces[p][(k + 1) % m];
      if (b == (a + 1) % n) continue;  // the polygon's edge a
      int across = 0;
      for (std::size_t q = 0; q < pieces.size(); ++q)
        for (std::size_t j = 0; j < pieces[q].size(); ++j)
          across += pieces[q][j] == b && pieces[q][(j + 1) % pieces[q].size()] == a;
      EXPECT_EQ(across, 1) << "diagonal " << a << "–" << b;
    }
  }
  EXPECT_NEAR(total, signed_area(polygon), 1e-12 * signed_area(polygon));
}

TEST(ConvexPieces, AConvexPolygonIsOnePiece) {
  const Polygon hexagon{{0.0, 0.0}, {3.0, -1.0}, {5.0, 1.0}, {4.5, 3.0}, {1.0, 3.5}, {-1.0, 2.0}};
  const auto pieces = convex_pieces(hexagon);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].size(), hexagon.size());
}

TEST(ConvexPieces, AnLIsTwoPieces) {
  const Polygon l{{0.0, 0.0}, {4.0, 0.0}, {4.0, 1.5}, {2.0, 1.5}, {2.0, 3.0}, {0.0, 3.0}};
  const auto pieces = convex_pieces(l);
  EXPECT_EQ(pieces.size(), 2u);
  expect_pieces(l, pieces);
}

// A straight corner (a vertex on a straight side, where a trace ended) stays in a piece.
TEST(ConvexPieces, ANotchAndAStraightCornerArePartitioned) {
  const Polygon notch{{0.0, 0.0}, {2.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}, {2.5, 3.0}, {2.0, 1.0}, {1.5, 3.0}, {0.0, 3.0}};
  const auto pieces = convex_pieces(notch);
  EXPECT_GE(pieces.size(), 2u);
  EXPECT_LE(pieces.size(), 8u);  // 4 × 2
  expect_pieces(notch, pieces);
}

// A quarter plate with a hole of radius 1 m, the arc as 16 chords: 15 reflex corners, so at
// least 9 pieces and by the bound at most 4 × that of the fewest.
TEST(ConvexPieces, AnArcOfReflexCornersIsPartitioned) {
  Polygon plate{{5.0, 0.0}, {5.0, 5.0}, {0.0, 5.0}};
  for (int k = 0; k <= 16; ++k) {
    const double angle = std::numbers::pi / 2.0 * (1.0 - k / 16.0);
    plate.push_back({std::cos(angle), std::sin(angle)});
  }
  const auto pieces = convex_pieces(plate);
  EXPECT_GE(pieces.size(), 9u);
  expect_pieces(plate, pieces);
}

TEST(ConvexPieces, AClockwisePolygonIsRefused) {
  const Polygon clockwise{{0.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {1.0, 0.0}};
  EXPECT_THROW(convex_pieces(clockwise), std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::geometry
