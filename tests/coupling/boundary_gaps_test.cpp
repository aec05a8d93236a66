// Boundary gaps are not fractures (coupling/boundary_gaps.hpp): the strip a block leaves
// between its face and the domain boundary is taken out of the open area, a fracture's open
// area is kept whole, and the distance a block reaches outside the mesh is reported.
// Exact identities of areas; tolerance 1e-12 (round-off of the clip).

#include <gtest/gtest.h>

#include <numeric>

#include "coupling/boundary_gaps.hpp"
#include "coupling/porosity.hpp"
#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Point;
using geometry::Polygon;

Polygon moved(const Polygon& p, Point by) {
  Polygon out;
  for (Point v : p) out.push_back(v + by);
  return out;
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(BoundaryGaps, ABlockPulledOffTheBoundaryLeavesNoOpenArea) {
  // One block filling the unit square, moved by (0.01, 0.02) into the domain's upper right: the
  // open area left inside the domain, 1 − 0.99 × 0.98 = 0.0298, is all boundary gap (the left
  // strip 0.01 × 0.98, the bottom strip 0.02 × 0.99 and the corner 0.01 × 0.02).
  const mesh::TriangleMesh mesh = testing::make_rectangle_mesh(0, 0, 1, 1, 7, 9);
  const Polygon domain{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Polygon> built{domain};
  const BoundaryGaps gaps(mesh.nodes, mesh.triangles, domain, built);
  EXPECT_EQ(gaps.boundary_face_count(), 4);
  const std::vector<Polygon> now{moved(domain, {0.01, 0.02})};
  const std::vector<double> gap = gaps.compute_gap_areas(now);
  EXPECT_NEAR(sum(gap), 0.0298, 1e-12);

  const PorosityMapper mapper(mesh.nodes, mesh.triangles);
  PorosityField field = mapper.compute(now, 0.1);
  EXPECT_NEAR(sum(field.fracture_area), 0.0298, 1e-12);
  exclude_boundary_gaps(field, gap, mapper.element_areas(), 0.1);
  for (std::size_t e = 0; e < gap.size(); ++e) {
    EXPECT_NEAR(field.fracture_area[e], 0.0, 1e-12) << "element " << e;
    EXPECT_NEAR(field.porosity[e], 0.1, 1e-10) << "element " << e;
  }
  // The block's upper right corner is 0.01 outside on the right and 0.02 above: 0.02236 m.
  const MeshExcursion out = gaps.find_excursion(now);
  EXPECT_EQ(out.block, 0);
  EXPECT_EQ(out.blocks_outside, 1);
  EXPECT_NEAR(out.distance, std::hypot(0.01, 0.02), 1e-12);
}

TEST(BoundaryGaps, AFractureKeepsItsOpenAreaWhereItMeetsTheBoundary) {
  // Two blocks 0.02 apart across x = 1 in a 2 × 1 domain, both lifted by 0.01 off the base:
  // of the open area 2 − 2 × 0.99 × 0.99 = 0.0398 the base strips (2 × 0.99 × 0.01) are gaps
  // and the fracture keeps 0.02 × 1, its mouth at the base included.
  const mesh::TriangleMesh mesh = testing::make_rectangle_mesh(0, 0, 2, 1, 12, 7);
  const Polygon domain{{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const std::vector<Polygon> built{{{0, 0}, {0.99, 0}, {0.99, 1}, {0, 1}}, {{1.01, 0}, {2, 0}, {2, 1}, {1.01, 1}}};
  const BoundaryGaps gaps(mesh.nodes, mesh.triangles, domain, built);
  EXPECT_EQ(gaps.boundary_face_count(), 6);  // the fracture's faces are not boundary faces
  const std::vector<Polygon> now{moved(built[0], {0, 0.01}), moved(built[1], {0, 0.01})};
  const std::vector<double> gap = gaps.compute_gap_areas(now);
  EXPECT_NEAR(sum(gap), 2 * 0.99 * 0.01, 1e-12);
  const PorosityMapper mapper(mesh.nodes, mesh.triangles);
  PorosityField field = mapper.compute(now, 0.0);
  exclude_boundary_gaps(field, gap, mapper.element_areas(), 0.0);
  EXPECT_NEAR(sum(field.fracture_area), 0.02, 1e-12);
  for (std::size_t e = 0; e < gap.size(); ++e) {
    const Point c = (mesh.nodes[mesh.triangles[e][0]] + mesh.nodes[mesh.triangles[e][1]] +
                     mesh.nodes[mesh.triangles[e][2]]) / 3.0;
    if (std::abs(c.x - 1.0) > 2.0 / 12) {
      EXPECT_NEAR(field.fracture_area[e], 0.0, 1e-12) << "element " << e;
    }
  }
  EXPECT_EQ(gaps.find_excursion(now).blocks_outside, 2);  // their tops are 0.01 above the domain
}

// Two blocks touching across x = 1 as built (a closed joint meeting the base), lifted by 0.01
// and moved 0.001 apart each way: the base strips (0.999 × 0.01 each) and the mouth between
// the two lifted corners (0.002 × 0.01) are all gap, 2 × 0.01 in all, and the joint keeps
// only its opening above the corners, 0.002 × 0.99. Without the mouth the 0.002 × 0.01 sliver
// below the corners read as joint, with the lift (0.01) as its local aperture.
TEST(BoundaryGaps, TheMouthOfAClosedJointLiftedOffTheBaseIsGap) {
  const mesh::TriangleMesh mesh = testing::make_rectangle_mesh(0, 0, 2, 1, 12, 7);
  const Polygon domain{{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const std::vector<Polygon> built{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}};
  const BoundaryGaps gaps(mesh.nodes, mesh.triangles, domain, built);
  const std::vector<Polygon> now{moved(built[0], {-0.001, 0.01}), moved(built[1], {0.001, 0.01})};
  const std::vector<double> gap = gaps.compute_gap_areas(now);
  EXPECT_NEAR(sum(gap), 2 * 0.01, 1e-12);
  const PorosityMapper mapper(mesh.nodes, mesh.triangles);
  PorosityField field = mapper.compute(now, 0.0);
  EXPECT_NEAR(sum(field.fracture_area), 2.0 - 2 * 0.999 * 0.99, 1e-12);
  exclude_boundary_gaps(field, gap, mapper.element_areas(), 0.0);
  EXPECT_NEAR(sum(field.fracture_area), 0.002 * 0.99, 1e-12);
  // Corners that close on each other leave no mouth, only the strips: the base strips 1 × 0.01
  // (overlapping by 0.002 × 0.01 under the corners), the corner rectangles 0.001 × 0.01 and
  // the side strips 0.001 × 0.99 of the blocks moved off the left and right sides.
  const std::vector<Polygon> pressed{moved(built[0], {0.001, 0.01}), moved(built[1], {-0.001, 0.01})};
  EXPECT_NEAR(sum(gaps.compute_gap_areas(pressed)), 2 * (0.01 + 0.001 * 0.01 + 0.001 * 0.99), 1e-12);
}

TEST(BoundaryGaps, ABlockPushedOutsideLeavesNoGapAndReportsHowFar) {
  // Moved 0.03 to the left: its left face lies outside (no gap), the right strip 0.03 wide is
  // the gap, and the block reaches 0.03 outside.
  const mesh::TriangleMesh mesh = testing::make_rectangle_mesh(0, 0, 1, 1, 5, 5);
  const Polygon domain{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const BoundaryGaps gaps(mesh.nodes, mesh.triangles, domain, std::vector<Polygon>{domain});
  const std::vector<Polygon> now{moved(domain, {-0.03, 0})};
  EXPECT_NEAR(sum(gaps.compute_gap_areas(now)), 0.03, 1e-12);
  const MeshExcursion out = gaps.find_excursion(now);
  EXPECT_NEAR(out.distance, 0.03, 1e-12);
  // A block inside the domain reports nothing outside.
  EXPECT_EQ(gaps.find_excursion(std::vector<Polygon>{moved(domain, {0.0, 0.0})}).blocks_outside, 0);
}

}  // namespace
}  // namespace hydrodda::coupling
