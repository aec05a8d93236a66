#include "coupling/porosity.hpp"

#include <gtest/gtest.h>

#include <random>

#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Polygon;

Polygon rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

TEST(Porosity, FractureAreaIsDomainMinusBlocks) {
  // Σ_e A_f,e = A_domain − Σ_blocks |block ∩ domain| (blocks disjoint): 1e-10 relative.
  // A 4 m × 3 m domain on an irregular-width mesh; blocks of a shrunk 3 × 2 grid, one of them
  // partly outside the domain, one non-convex.
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 4.0, 3.0, 37, 29);
  PorosityMapper mapper(mesh.nodes, mesh.triangles);
  std::vector<Polygon> blocks{
      rectangle(0.0, 0.0, 1.3, 1.45), rectangle(1.33, 0.0, 2.61, 1.45), rectangle(2.64, 0.0, 4.5, 1.45),
      // An L-shaped block (non-convex).
      {{0.0, 1.5}, {2.0, 1.5}, {2.0, 2.2}, {1.0, 2.2}, {1.0, 3.0}, {0.0, 3.0}},
      rectangle(2.05, 1.5, 4.0, 3.0)};
  const PorosityField field = mapper.compute(blocks, 0.0);
  double fracture = 0.0;
  for (double a : field.fracture_area) fracture += a;
  // Block areas inside the domain: the third block loses x in [4, 4.5].
  const double blocks_inside = 1.3 * 1.45 + 1.28 * 1.45 + 1.36 * 1.45 + (2.0 * 0.7 + 1.0 * 0.8) + 1.95 * 1.5;
  const double expected = 12.0 - blocks_inside;
  EXPECT_NEAR(fracture, expected, 1e-10 * 12.0);
}

TEST(Porosity, EquationEightAndClamping) {
  // One element a quarter covered: φ = ¾(1 − φ_m) + φ_m. Overlapping blocks covering it twice: φ_m.
  mesh::TriangleMesh m;
  m.nodes = {{0, 0}, {1, 0}, {0, 1}};
  m.triangles = {{0, 1, 2}};
  PorosityMapper mapper(m.nodes, m.triangles);
  const double phi_m = 0.1;
  // The block covers x ≥ 0.5: of the triangle (0,0), (1,0), (0,1) that is the corner triangle
  // (0.5,0), (1,0), (0.5,0.5) of area 0.125, a quarter; the open area is 0.375.
  const PorosityField quarter = mapper.compute(std::vector<Polygon>{rectangle(0.5, 0.0, 2.0, 2.0)}, phi_m);
  EXPECT_NEAR(quarter.fracture_area[0], 0.375, 1e-15);
  EXPECT_NEAR(quarter.porosity[0], 0.75 * (1.0 - phi_m) + phi_m, 1e-15);
  const PorosityField twice =
      mapper.compute(std::vector<Polygon>{rectangle(-1, -1, 2, 2), rectangle(-1, -1, 2, 2)}, phi_m);
  EXPECT_EQ(twice.fracture_area[0], 0.0);
  EXPECT_EQ(twice.porosity[0], phi_m);
  const PorosityField open = mapper.compute(std::vector<Polygon>{}, phi_m);
  EXPECT_EQ(open.porosity[0], 1.0);
  EXPECT_THROW(mapper.compute(std::vector<Polygon>{}, 1.0), std::invalid_argument);
}

TEST(Porosity, EachPassRecomputesFromTheBlocksGiven) {
  // The mapper keeps only the mesh: moving a block changes the field (no stale porosity).
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 1.0, 1.0, 10, 10);
  PorosityMapper mapper(mesh.nodes, mesh.triangles);
  const auto first = mapper.compute(std::vector<Polygon>{rectangle(0.0, 0.0, 0.5, 1.0)}, 0.0);
  const auto second = mapper.compute(std::vector<Polygon>{rectangle(0.5, 0.0, 1.0, 1.0)}, 0.0);
  double sum_first = 0.0, sum_second = 0.0;
  int changed = 0;
  for (std::size_t e = 0; e < first.porosity.size(); ++e) {
    sum_first += first.fracture_area[e];
    sum_second += second.fracture_area[e];
    changed += first.porosity[e] != second.porosity[e];
  }
  EXPECT_NEAR(sum_first, 0.5, 1e-14);
  EXPECT_NEAR(sum_second, 0.5, 1e-14);
  EXPECT_EQ(changed, 200);  // every element flips between covered and open
}

TEST(Porosity, PiecesTileEachBlockInsideTheMesh) {
  // The pieces of a block (one per element it covers) have the block's area and first moment:
  // Σ A_k = A_block and Σ A_k c_k = A_block c_block, 1e-12 relative (of A L for the moment);
  // the part of a block outside the mesh has no piece. The fracture areas are those of the
  // field computed without pieces, bit for bit.
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 4.0, 3.0, 37, 29);
  PorosityMapper mapper(mesh.nodes, mesh.triangles);
  const std::vector<Polygon> blocks{
      rectangle(0.21, 0.13, 1.3, 1.45),
      {{0.0, 1.5}, {2.0, 1.5}, {2.0, 2.2}, {1.0, 2.2}, {1.0, 3.0}, {0.0, 3.0}},  // L-shaped
      {{2.5, 0.4}, {3.7, 0.9}, {3.1, 2.6}},
      rectangle(3.5, 2.5, 4.5, 3.0)};  // half outside the mesh
  BlockPieces lists;
  const PorosityField with = mapper.compute(blocks, 0.1, &lists);
  std::vector<BlockPiece> pieces;
  for (const std::vector<BlockPiece>& list : lists.lists()) pieces.insert(pieces.end(), list.begin(), list.end());
  const PorosityField without = mapper.compute(blocks, 0.1);
  EXPECT_EQ(with.fracture_area, without.fracture_area);
  EXPECT_EQ(with.porosity, without.porosity);
  // In element order, each pair once (what the seepage force's sums rely on to be the same on
  // any number of threads).
  for (std::size_t k = 1; k < pieces.size(); ++k)
    EXPECT_TRUE(pieces[k - 1].element < pieces[k].element ||
                (pieces[k - 1].element == pieces[k].element && pieces[k - 1].block != pieces[k].block))
        << "piece " << k;
  std::vector<double> area(blocks.size(), 0.0);
  std::vector<Point> moment(blocks.size());
  for (const BlockPiece& piece : pieces) {
    ASSERT_GE(piece.block, 0);
    ASSERT_LT(piece.block, static_cast<int>(blocks.size()));
    EXPECT_GT(piece.area, 0.0);
    area[piece.block] += piece.area;
    moment[piece.block] += piece.area * piece.centroid;
  }
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Polygon inside = b < 3 ? blocks[b] : rectangle(3.5, 2.5, 4.0, 3.0);
    const double a = geometry::area(inside);
    const Point first_moment = a * geometry::centroid(inside);
    EXPECT_NEAR(area[b], a, 1e-12 * a) << "block " << b;
    EXPECT_NEAR(moment[b].x, first_moment.x, 1e-12 * a * 5.0) << "block " << b;
    EXPECT_NEAR(moment[b].y, first_moment.y, 1e-12 * a * 5.0) << "block " << b;
  }
}

}  // namespace
}  // namespace hydrodda::coupling
