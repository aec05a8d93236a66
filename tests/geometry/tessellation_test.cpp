// Tessellation of a polygon into sub-blocks (geometry/tessellation.hpp): exact
// identities of a partition. The sub-blocks' areas sum to the polygon's (to 1e-12 of it:
// round-off of the clipping; the welding of vertices within 1e-2 size moves no vertex of a
// face that stays, only ends of faces shorter than that); every face names its neighbour and
// is named back, along the same segment (to 1e-9 m); each Voronoi cell holds its seed and
// no other seed is nearer any of its vertices (to 2e-2 size: the welding moves a vertex by up to 1e-2 size).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "geometry/polygon.hpp"
#include "geometry/tessellation.hpp"

namespace hydrodda::geometry {
namespace {

const Polygon kSquare{{0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}, {0.0, 3.0}};
constexpr double kSize = 0.5;

Tessellation tessellate(const Polygon& polygon, TessellationKind kind, std::uint64_t seed = 7) {
  const std::vector<Point> seeds = select_seeds(polygon, generate_seeds(bounding_box(polygon), kSize, seed), 0.2 * kSize);
  return tessellate(polygon, seeds, kSize, kind);
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
      // The neighbour has the same face, run the other way (two sub-blocks may meet along
      // two faces beside a reflex corner: one of its edges named back has these ends).
      const Polygon& other = t.cells[static_cast<std::size_t>(source)];
      int back = -1;
      for (std::size_t f = 0; f < other.size(); ++f)
        if (t.edge_sources[static_cast<std::size_t>(source)][f] == static_cast<int>(c) &&
            distance(a, other[(f + 1) % other.size()]) < 1e-9 && distance(b, other[f]) < 1e-9)
          back = static_cast<int>(f);
      EXPECT_GE(back, 0) << "sub-block " << c << " edge " << e;
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
  const Tessellation t = tessellate(kSquare, seeds, kSize, TessellationKind::voronoi);
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

// Each triangle names the Voronoi cell it was fanned from: one triangle per edge of that cell,
// its first edge the cell's own, the two spokes to triangles of the same cell; a Voronoi cell
// names itself.
TEST(Tessellation, EachTriangleNamesTheCellItWasFannedFrom) {
  const Tessellation cells = tessellate(kSquare, TessellationKind::voronoi);
  const Tessellation triangles = tessellate(kSquare, TessellationKind::triangles);
  ASSERT_EQ(cells.cell_of.size(), cells.cells.size());
  for (std::size_t c = 0; c < cells.cells.size(); ++c) EXPECT_EQ(cells.cell_of[c], static_cast<int>(c));
  ASSERT_EQ(triangles.cell_of.size(), triangles.cells.size());
  std::vector<std::size_t> count(cells.cells.size(), 0);
  for (std::size_t t = 0; t < triangles.cells.size(); ++t) {
    const int c = triangles.cell_of[t];
    ASSERT_GE(c, 0);
    ASSERT_LT(c, static_cast<int>(cells.cells.size()));
    ++count[static_cast<std::size_t>(c)];
    for (std::size_t e : {1u, 2u}) {
      const int across = triangles.edge_sources[t][e];
      ASSERT_GE(across, 0) << "triangle " << t << ": a spoke on the outline";
      EXPECT_EQ(triangles.cell_of[static_cast<std::size_t>(across)], c) << "triangle " << t << ", edge " << e;
    }
  }
  for (std::size_t c = 0; c < cells.cells.size(); ++c) EXPECT_EQ(count[c], cells.cells[c].size()) << "cell " << c;
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
  const Tessellation t = tessellate(kSquare, seeds, kSize, TessellationKind::voronoi);
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

// The sub-blocks of a convex polygon as the tessellation made them before it took polygons
// that are not convex (the Voronoi cells of 9 seeds in a pentagon, written as %a of the
// doubles): bit for bit the same vertices and labels.
TEST(Tessellation, AConvexPolygonGivesTheCellsItGaveBefore) {
  const Polygon pentagon{{0.0, 0.0}, {1.6, -0.2}, {2.0, 0.9}, {1.1, 1.7}, {-0.1, 1.2}};
  const std::vector<std::pair<Polygon, std::vector<int>>> expected{
{{{0x0p+0, 0x0p+0},
     {0x1.fb1905937c11dp-1, -0x1.fb1905937c11dp-4},
     {0x1.faeab76702dd8p-1, -0x1.127813548c80cp-4},
     {0x1.60d451e17c946p-1, 0x1.c5a5cf872ae24p-2},
     {-0x1.441b4118a9adap-5, 0x1.e628e1a4fe846p-2}},
     {-1, 1, 3, 2, -5}},
{{{0x1.fb1905937c11dp-1, -0x1.fb1905937c11dp-4},
     {0x1.999999999999ap+0, -0x1.999999999999ap-3},
     {0x1.ca7e484af2852p+0, 0x1.4d06b4d205519p-2},
     {0x1.483b63ddac2c7p+0, 0x1.591b056a9058ep-2},
     {0x1.faeab76702dd8p-1, -0x1.127813548c80cp-4}},
     {-1, -2, 4, 3, 0}},
{{{0x1.60d451e17c946p-1, 0x1.c5a5cf872ae24p-2},
     {0x1.d4c56590822c5p-1, 0x1.9d157a1213768p-1},
     {0x1.851c871cd9301p-1, 0x1.fe4bd6127d878p-1},
     {-0x1.ecd1cf36e2206p-5, 0x1.719d5b6929984p-1},
     {-0x1.441b4118a9adap-5, 0x1.e628e1a4fe846p-2}},
     {3, 6, 5, -5, 0}},
{{{0x1.faeab76702dd8p-1, -0x1.127813548c80cp-4},
     {0x1.483b63ddac2c7p+0, 0x1.591b056a9058ep-2},
     {0x1.34a0aa64c5c4dp+0, 0x1.99b40e38534c4p-1},
     {0x1.316437d1588f7p+0, 0x1.9ebe8de744687p-1},
     {0x1.d4c56590822c5p-1, 0x1.9d157a1213768p-1},
     {0x1.60d451e17c946p-1, 0x1.c5a5cf872ae24p-2}},
     {1, 4, 7, 6, 2, 0}},
{{{0x1.ca7e484af2852p+0, 0x1.4d06b4d205519p-2},
     {0x1.f295ddad2b2d6p+0, 0x1.830510053a464p-1},
     {0x1.34a0aa64c5c4dp+0, 0x1.99b40e38534c4p-1},
     {0x1.483b63ddac2c7p+0, 0x1.591b056a9058ep-2}},
     {-2, 7, 3, 1}},
{{{0x1.10b509ab105f2p-1, 0x1.76ae3fe18147p+0},
     {-0x1.999999999999ap-4, 0x1.3333333333333p+0},
     {-0x1.ecd1cf36e2206p-5, 0x1.719d5b6929984p-1},
     {0x1.851c871cd9301p-1, 0x1.fe4bd6127d878p-1},
     {0x1.6e60bbcaee25bp-1, 0x1.3952aa8f0cad3p+0}},
     {-4, -5, 2, 6, 8}},
{{{0x1.316437d1588f7p+0, 0x1.9ebe8de744687p-1},
     {0x1.5896090cdb42cp+0, 0x1.67b8c785d1e1ep+0},
     {0x1.6e60bbcaee25bp-1, 0x1.3952aa8f0cad3p+0},
     {0x1.851c871cd9301p-1, 0x1.fe4bd6127d878p-1},
     {0x1.d4c56590822c5p-1, 0x1.9d157a1213768p-1}},
     {7, 8, 5, 2, 3}},
{{{0x1.f295ddad2b2d6p+0, 0x1.830510053a464p-1},
     {0x1p+1, 0x1.ccccccccccccdp-1},
     {0x1.61232d86f4f62p+0, 0x1.739c76d1fe6f2p+0},
     {0x1.5896090cdb42cp+0, 0x1.67b8c785d1e1ep+0},
     {0x1.316437d1588f7p+0, 0x1.9ebe8de744687p-1},
     {0x1.34a0aa64c5c4dp+0, 0x1.99b40e38534c4p-1}},
     {-2, -3, 8, 6, 3, 4}},
{{{0x1.61232d86f4f62p+0, 0x1.739c76d1fe6f2p+0},
     {0x1.199999999999ap+0, 0x1.b333333333333p+0},
     {0x1.10b509ab105f2p-1, 0x1.76ae3fe18147p+0},
     {0x1.6e60bbcaee25bp-1, 0x1.3952aa8f0cad3p+0},
     {0x1.5896090cdb42cp+0, 0x1.67b8c785d1e1ep+0}},
     {-3, -4, 5, 6, 7}},
  };
  const std::vector<Point> seeds = select_seeds(pentagon, generate_seeds(bounding_box(pentagon), 0.5, 5), 0.1);
  const Tessellation t = tessellate(pentagon, seeds, 0.5, TessellationKind::voronoi);
  ASSERT_EQ(t.cells.size(), expected.size());
  for (std::size_t c = 0; c < expected.size(); ++c) {
    EXPECT_EQ(t.cells[c], expected[c].first) << "sub-block " << c;
    EXPECT_EQ(t.edge_sources[c], expected[c].second) << "sub-block " << c;
  }
}

// Non-convex polygons: an L (one reflex corner at (2, 1.5)) and a square with a V notch cut
// into its top (a reflex corner at (2, 1)). The sub-blocks partition the polygon as a convex
// one's do (expect_partition), counter-clockwise, each convex up to the welding: no vertex
// stands more than 1e-2 size inside the line through its neighbours (the welding moves a
// vertex by up to that; before it, the cells are convex to round-off).
const Polygon kL{{0.0, 0.0}, {4.0, 0.0}, {4.0, 1.5}, {2.0, 1.5}, {2.0, 3.0}, {0.0, 3.0}};
const Polygon kNotch{{0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}, {2.5, 3.0}, {2.0, 1.0}, {1.5, 3.0}, {0.0, 3.0}};

void expect_convex(const Tessellation& t, double size) {
  for (std::size_t c = 0; c < t.cells.size(); ++c) {
    const Polygon& cell = t.cells[c];
    const std::size_t n = cell.size();
    EXPECT_GT(signed_area(cell), 0.0) << "sub-block " << c;
    for (std::size_t k = 0; k < n; ++k) {
      const Point a = cell[k], b = cell[(k + 1) % n], d = cell[(k + 2) % n];
      // orient / |ad|: how far b stands left of the line a → d (negative: inside).
      EXPECT_GE(orient(a, b, d) / distance(a, d), -1e-2 * size) << "sub-block " << c << " vertex " << k + 1;
    }
  }
}

// A quarter of a square plate 5 m across with a hole of radius 1 m at its corner, the arc as
// 16 chords: 15 reflex corners.
Polygon quarter_plate_with_hole() {
  Polygon plate{{5.0, 0.0}, {5.0, 5.0}, {0.0, 5.0}};
  for (int k = 0; k <= 16; ++k) {
    const double angle = std::numbers::pi / 2.0 * (1.0 - k / 16.0);
    plate.push_back({std::cos(angle), std::sin(angle)});
  }
  return plate;
}

TEST(Tessellation, NonConvexPolygonsArePartitionedIntoConvexSubBlocks) {
  for (const Polygon& polygon : {kL, kNotch, quarter_plate_with_hole()})
    for (const TessellationKind kind : {TessellationKind::voronoi, TessellationKind::triangles})
      for (std::uint64_t seed : {1u, 2u, 3u, 7u}) {
        SCOPED_TRACE("polygon of " + std::to_string(polygon.size()) + " corners, seed " + std::to_string(seed));
        const Tessellation t = tessellate(polygon, kind, seed);
        expect_partition(polygon, t);
        expect_convex(t, kSize);
      }
}

// Voronoi cells of a non-convex polygon: each seed lies in one sub-block, and a sub-block that
// holds no seed is a part of its seed's cell (the seed nearest its centroid) cut off either at
// a reflex corner (the corner is one of its vertices) or by the outside of the polygon (the
// segment from the seed to it leaves the polygon: a cell reaching across the notch); in the L,
// the notch and the quarter plate (its 15 reflex corners along the arc).
TEST(Tessellation, AVoronoiCellIsSplitOnlyAtAReflexCornerOrByTheOutside) {
  const Polygon plate = quarter_plate_with_hole();
  const std::vector<std::pair<Polygon, std::vector<Point>>> cases{
      {kL, {{2.0, 1.5}}}, {kNotch, {{2.0, 1.0}}}, {plate, std::vector<Point>(plate.begin() + 4, plate.end() - 1)}};
  for (const auto& [polygon, reflexes] : cases)
    for (std::uint64_t seed : {1u, 2u, 3u, 7u}) {
      const std::vector<Point> seeds = select_seeds(polygon, generate_seeds(bounding_box(polygon), kSize, seed), 0.2 * kSize);
      const Tessellation t = tessellate(polygon, seeds, kSize, TessellationKind::voronoi);
      for (Point s : seeds) {
        const auto holding = std::count_if(t.cells.begin(), t.cells.end(), [&](const Polygon& c) { return contains(c, s); });
        EXPECT_EQ(holding, 1) << "seed " << seed << " at (" << s.x << ", " << s.y << ")";
      }
      for (const Polygon& cell : t.cells) {
        if (std::any_of(seeds.begin(), seeds.end(), [&](Point s) { return contains(cell, s); })) continue;
        const Point middle = centroid(cell);
        const Point owner = *std::min_element(seeds.begin(), seeds.end(), [&](Point a, Point b) {
          return distance(a, middle) < distance(b, middle);
        });
        const bool at_corner = std::any_of(reflexes.begin(), reflexes.end(), [&](Point reflex) {
          return std::find(cell.begin(), cell.end(), reflex) != cell.end();
        });
        const auto inside = clip_segment_to_polygon(owner, middle, polygon);
        const bool across_outside = inside.size() != 1 || inside[0].first > 1e-12 || inside[0].second < 1.0 - 1e-12;
        EXPECT_TRUE(at_corner || across_outside)
            << "seed " << seed << ": a sub-block at (" << middle.x << ", " << middle.y << ") without its seed";
      }
    }
}

// Two seeds mirrored across the line y = x − 1, which crosses the L's foot from (1, 0) to
// (2.5, 1.5) and passes 0.5/√2 m below its reflex corner (2, 1.5): seed (3.5, 0.5)'s cell is
// the trapezoid (1, 0), (4, 0), (4, 1.5), (2.5, 1.5), convex, one sub-block of area
// (3 + 1.5)/2 · 1.5 = 3.375 m² whatever seam crosses it; seed (1.5, 2.5)'s cell, the rest,
// holds the reflex corner and is cut there into two sub-blocks bonded along the seam.
TEST(Tessellation, TwoSeedsInAnLMakeThreeSubBlocks) {
  const std::vector<Point> seeds{{3.5, 0.5}, {1.5, 2.5}};
  const Tessellation t = tessellate(kL, seeds, kSize, TessellationKind::voronoi);
  expect_partition(kL, t);
  expect_convex(t, kSize);
  ASSERT_EQ(t.cells.size(), 3u);
  int below = 0;
  for (const Polygon& cell : t.cells) {
    const Point c = centroid(cell);
    if (c.y >= c.x - 1.0) continue;
    ++below;
    EXPECT_NEAR(signed_area(cell), 3.375, 1e-12);
  }
  EXPECT_EQ(below, 1);
}

TEST(Tessellation, ASelfIntersectingPolygonIsRefused) {
  const Polygon bow{{0.0, 0.0}, {4.0, 3.0}, {4.0, 0.0}, {3.0, 2.0}, {0.0, 3.0}};
  EXPECT_THROW(tessellate(bow, std::vector<Point>{{1.0, 0.5}, {3.0, 0.5}}, kSize, TessellationKind::voronoi),
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
    const Tessellation t = tessellate(kSquare, seeds, pairs.spacing, kind);
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

// A reflex corner's seeds (make_reflex_corner_seeds), on the L's corner (2, 1.5): its angle
// α = 270° runs from the outgoing edge (direction 90°) round to the incoming one run back (0°),
// so the seeds lie size/2 from the corner at 90° + α/4 = 157.5° and 90° + 3α/4 = 292.5°, mirror
// images across the bisector at 225° (to 1e-12 m: one rotation).
TEST(Tessellation, AReflexCornersSeedsAreMirroredAcrossItsBisector) {
  const std::vector<ReflexCornerSeeds> corners = make_reflex_corner_seeds(kL, kSize, 0.2 * kSize);
  ASSERT_EQ(corners.size(), 1u);
  EXPECT_EQ(corners[0].corner, (Point{2.0, 1.5}));
  const double degree = std::numbers::pi / 180.0;
  for (int k = 0; k < 2; ++k) {
    const double angle = (k == 0 ? 157.5 : 292.5) * degree;
    EXPECT_NEAR(corners[0].seeds[k].x, 2.0 + 0.25 * std::cos(angle), 1e-12);
    EXPECT_NEAR(corners[0].seeds[k].y, 1.5 + 0.25 * std::sin(angle), 1e-12);
  }
  EXPECT_TRUE(make_reflex_corner_seeds(kSquare, kSize, 0.2 * kSize).empty());
}

// The grid's seeds within size of a reflex corner replaced by its two seeds: the corner is a
// vertex of exactly two Voronoi sub-blocks, the cells of those seeds, and no cell is split at
// it: in the L every sub-block holds a seed (one per seed); in the V notch, whose cells may
// reach across the notch, the corner's two sub-blocks hold its seeds. Before, the cell holding
// the corner wrapped round it and was split there into convex parts, one as small as its reach
// past the corner's lines.
TEST(Tessellation, AReflexCornersSeedsMakeItANodeOfTwoCells) {
  for (const Polygon& polygon : {kL, kNotch})
    for (std::uint64_t seed : {1u, 2u, 3u, 7u}) {
      SCOPED_TRACE("polygon of " + std::to_string(polygon.size()) + " corners, seed " + std::to_string(seed));
      const std::vector<ReflexCornerSeeds> corners = make_reflex_corner_seeds(polygon, kSize, 0.2 * kSize);
      ASSERT_EQ(corners.size(), 1u);
      std::vector<Point> seeds;
      for (Point s : select_seeds(polygon, generate_seeds(bounding_box(polygon), kSize, seed), 0.2 * kSize))
        if (distance(s, corners[0].corner) >= kSize) seeds.push_back(s);
      seeds.insert(seeds.end(), corners[0].seeds.begin(), corners[0].seeds.end());
      const Tessellation t = tessellate(polygon, seeds, kSize, TessellationKind::voronoi);
      expect_partition(polygon, t);
      expect_convex(t, kSize);
      if (polygon == kL) EXPECT_EQ(t.cells.size(), seeds.size());
      std::vector<std::size_t> at_corner;
      for (std::size_t c = 0; c < t.cells.size(); ++c)
        if (std::find(t.cells[c].begin(), t.cells[c].end(), corners[0].corner) != t.cells[c].end()) at_corner.push_back(c);
      ASSERT_EQ(at_corner.size(), 2u);
      for (Point s : corners[0].seeds)
        EXPECT_TRUE(contains(t.cells[at_corner[0]], s) || contains(t.cells[at_corner[1]], s));
    }
}

}  // namespace
}  // namespace hydrodda::geometry
