// The triangle count estimated before meshing (mesh_estimate.hpp) against Gmsh's real count:
// within a factor 1.5 either way, on a uniform square, an L-shape, one refined fracture, a
// dense network whose refinement bands overlap and a coarse grid of cells (a tiny
// fracture_size). Small meshes (≤ 60,000 triangles), so that the test takes seconds.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_estimate.hpp"
#include "mesh/mesh_request.hpp"

namespace hydrodda::mesh {
namespace {

constexpr double kFactor = 1.5;  // the documented accuracy of the estimate

void expect_estimate_within_factor(const MeshRequest& request) {
  const double estimate = estimate_triangle_count(request).total();
  const double actual = generate_mesh(request).triangle_count();
  EXPECT_LT(estimate, kFactor * actual) << "estimate " << estimate << ", Gmsh " << actual;
  EXPECT_GT(estimate, actual / kFactor) << "estimate " << estimate << ", Gmsh " << actual;
}

TEST(MeshEstimate, UniformSquare) {
  MeshRequest request;
  request.domain = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  request.size = 0.02;
  expect_estimate_within_factor(request);
}

TEST(MeshEstimate, LShapeCountsOnlyItsArea) {
  MeshRequest request;
  request.domain = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  request.size = 0.03;
  expect_estimate_within_factor(request);
  // Three quarters of its box: a box-sized estimate would be 4/3 of it.
  MeshRequest box = request;
  box.domain = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_NEAR(estimate_triangle_count(request).total() / estimate_triangle_count(box).total(), 0.75, 0.02);
}

// A 2 m × 1 m domain with one fracture refined to 5 mm.
MeshRequest one_refined_fracture() {
  MeshRequest request;
  request.domain = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  request.size = 0.1;
  request.fracture_size = 0.005;
  request.refine_distance = 0.2;
  request.refinement_lines = {{{0.1, 0.3}, {1.9, 0.7}}};
  return request;
}

TEST(MeshEstimate, OneRefinedFracture) {
  const MeshRequest request = one_refined_fracture();
  const TriangleEstimate estimate = estimate_triangle_count(request);
  EXPECT_GT(estimate.near_lines, estimate.elsewhere);  // the band holds most of them
  expect_estimate_within_factor(request);
}

// Refinement points around a fracture's wedge tips, on top of its refined band, growing by a
// fifth of the distance (the reader's default).
TEST(MeshEstimate, RefinementPoints) {
  MeshRequest request = one_refined_fracture();
  request.refinement_points = {{{0.5, 0.6}, 0.0002, (0.1 - 0.0002) / 0.2}, {{1.5, 0.3}, 0.0005, (0.1 - 0.0005) / 0.2}};
  EXPECT_GT(estimate_triangle_count(request).near_points, 0.0);
  expect_estimate_within_factor(request);
}

TEST(MeshEstimate, DenseNetworkWithOverlappingBands) {
  MeshRequest request;
  request.domain = {{0, 0}, {4, 0}, {4, 2}, {0, 2}};
  request.size = 0.1;
  request.fracture_size = 0.02;
  request.refine_distance = 0.2;
  for (int k = 1; k < 20; ++k) request.refinement_lines.push_back({{0.2 * k, 0.0}, {0.2 * k + 0.05, 2.0}});
  for (int k = 1; k < 10; ++k) request.refinement_lines.push_back({{0.0, 0.2 * k}, {4.0, 0.2 * k - 0.03}});
  expect_estimate_within_factor(request);
}

// A fracture_size so small that a grid cell is far wider than its triangles: the band is
// still weighed by the exact mean of 1/h² across each cell.
TEST(MeshEstimate, CellsWiderThanTheFinestTriangles) {
  MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.1;
  request.fracture_size = 0.0005;
  request.refine_distance = 0.4;
  request.refinement_lines = {{{0.0, 0.5}, {1.0, 0.5}}};
  expect_estimate_within_factor(request);
}

}  // namespace
}  // namespace hydrodda::mesh
