// Biot's effective stress: the faces' share (1 − α) of the pressure and the seepage force −α ∇p
// inside, handed to DDA as vertex forces with the load's resultant and first moments.

#include "coupling/seepage_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "coupling/porosity.hpp"
#include "coupling/pressure_forces.hpp"
#include "dda/block_kernels.hpp"
#include "hydro/element_pressure.hpp"
#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Polygon;

// A pressure far from linear (about 10 MPa, varying by some 40%).
double wavy_pressure(Point x) { return 1e7 * (1.0 + 0.3 * std::sin(3.0 * x.x + 1.0) * std::cos(2.0 * x.y) + 0.1 * x.x * x.y); }

const std::vector<Polygon> kBlocks{
    {{0.1, 0.1}, {0.9, 0.2}, {0.7, 0.8}},
    {{1.0, 1.0}, {1.6, 1.05}, {1.9, 1.7}, {1.3, 1.4}, {1.05, 1.8}},  // non-convex
    {{0.2, 1.1}, {0.8, 1.0}, {0.85, 1.9}, {0.15, 1.7}},
    {{1.7, 0.2}, {2.3, 0.3}, {2.25, 0.9}, {1.75, 0.8}},  // partly outside the mesh (x > 2)
};

// The fluid forces of the coupling loop for every block at one α: faces and seepage.
std::vector<std::vector<Point>> fluid_forces(const mesh::TriangleMesh& mesh, const std::vector<double>& p, double alpha) {
  const std::vector<double> biot(kBlocks.size(), alpha);
  BlockPieces pieces;
  PorosityMapper(mesh.nodes, mesh.triangles).compute(kBlocks, 0.0, &pieces);
  auto forces = FacePressureLoads(mesh).compute(kBlocks, p, biot);
  const auto seepage = compute_seepage_forces(kBlocks, pieces, hydro::compute_pressure_gradients(mesh, p), biot);
  for (std::size_t b = 0; b < forces.size(); ++b)
    for (std::size_t v = 0; v < forces[b].size(); ++v) forces[b][v] += seepage[b][v];
  return forces;
}

// DDA's load of vertex forces on the block's six unknowns about its centroid: Σ Tᵀ(x_v) F_v.
dda::Vector6 dda_load(const Polygon& block, const std::vector<Point>& forces) {
  const Point centroid = geometry::centroid(block);
  dda::Vector6 load = dda::Vector6::Zero();
  for (std::size_t v = 0; v < block.size(); ++v)
    load += dda::compute_displacement_matrix(block[v], centroid).transpose() * Eigen::Vector2d(forces[v].x, forces[v].y);
  return load;
}

TEST(SeepageForces, NetForceAndMomentDoNotDependOnAlpha) {
  // Divergence theorem: −∫_B ∇p dA = ∮ p n_in ds for the continuous P1 p, so the net force
  // and moment of each block are the same at α = 0 (all on the faces) and α = 1 (all inside),
  // for any pressure field: 1e-10 of p_max × perimeter (× size for the moment). The last
  // block sticks out of the mesh, where its faces take the rule outside the mesh and the mesh
  // boundary across it the part of the seepage force the mesh cannot hold.
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 31, 27);
  std::vector<double> p;
  for (Point n : mesh.nodes) p.push_back(wavy_pressure(n));
  const auto total = fluid_forces(mesh, p, 0.0);
  const auto effective = fluid_forces(mesh, p, 1.0);
  const auto half = fluid_forces(mesh, p, 0.5);
  for (std::size_t b = 0; b < kBlocks.size(); ++b) {
    double perimeter = 0.0;
    for (std::size_t i = 0; i < kBlocks[b].size(); ++i)
      perimeter += geometry::distance(kBlocks[b][i], kBlocks[b][(i + 1) % kBlocks[b].size()]);
    const double scale = 1.4e7 * perimeter;
    const dda::Vector6 at_0 = dda_load(kBlocks[b], total[b]);
    for (const auto* other : {&effective, &half}) {
      const dda::Vector6 at_alpha = dda_load(kBlocks[b], (*other)[b]);
      // Translations and rotation (the moment about the centroid).
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(at_alpha[k], at_0[k], 1e-10 * scale) << "block " << b << ", unknown " << k;
    }
    EXPECT_GT(std::abs(at_0[0]) + std::abs(at_0[1]), 1e-3 * scale) << "block " << b << ": a field with a net force";
  }
}

TEST(SeepageForces, StrainLoadDiffersByAlphaTimesTheIntegralOfPressure) {
  // Only the strains' load depends on α: the seepage force adds α ∫_B p dA to εx and εy (and
  // nothing to γxy) over the faces' α = 0 load, since ∫ x_i ∂_j p dA = ∮ x_i p n_j ds − δ_ij ∫ p dA.
  // ∫_B p dA is exact from the pieces (p linear in each: A_k p(c_k)). 1e-10 relative.
  // Uniform pressure at α = 1: no load at all (the joint test's case).
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 31, 27);
  std::vector<double> p;
  for (Point n : mesh.nodes) p.push_back(wavy_pressure(n));
  BlockPieces pieces;
  PorosityMapper(mesh.nodes, mesh.triangles).compute(kBlocks, 0.0, &pieces);
  std::vector<double> integral(kBlocks.size(), 0.0);
  for (const std::vector<BlockPiece>& list : pieces.lists())
    for (const BlockPiece& piece : list)
      integral[piece.block] += piece.area * hydro::interpolate_pressure(mesh, p, piece.element, piece.centroid);
  const auto total = fluid_forces(mesh, p, 0.0);
  const auto effective = fluid_forces(mesh, p, 1.0);
  for (std::size_t b = 0; b + 1 < kBlocks.size(); ++b) {  // the blocks inside the mesh
    const dda::Vector6 difference = dda_load(kBlocks[b], effective[b]) - dda_load(kBlocks[b], total[b]);
    EXPECT_NEAR(difference[3], integral[b], 1e-10 * integral[b]) << "block " << b;
    EXPECT_NEAR(difference[4], integral[b], 1e-10 * integral[b]) << "block " << b;
    EXPECT_NEAR(difference[5], 0.0, 1e-10 * integral[b]) << "block " << b;
  }
  const std::vector<double> uniform(mesh.nodes.size(), 1e7);
  const auto none = fluid_forces(mesh, uniform, 1.0);
  for (std::size_t b = 0; b + 1 < kBlocks.size(); ++b)
    for (Point f : none[b]) EXPECT_LE(geometry::norm(f), 1e-12 * 1e7) << "block " << b;
}

TEST(ForceMoments, VertexForcesKeepTheResultantAndFirstMoments) {
  // distribute_to_vertices: Σ F_v = R and Σ (x_v − o) ⊗ F_v = M, 1e-12 relative, for random
  // loads on a triangle, a square and a non-convex pentagon; a degenerate polygon is refused.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Polygon& block : kBlocks) {
    for (int trial = 0; trial < 20; ++trial) {
      ForceMoments m;
      m.origin = {u(rng), u(rng)};
      for (int k = 0; k < 5; ++k) m.add({u(rng), u(rng)}, {u(rng), u(rng)});
      m.add_along({u(rng), u(rng)}, {u(rng), u(rng)}, u(rng), u(rng), {0.6, 0.8});
      const std::vector<Point> forces = distribute_to_vertices(block, m);
      ForceMoments back;
      back.origin = m.origin;
      for (std::size_t v = 0; v < block.size(); ++v) back.add(block[v], forces[v]);
      const double scale = 10.0;
      EXPECT_NEAR(back.resultant.x, m.resultant.x, 1e-12 * scale);
      EXPECT_NEAR(back.resultant.y, m.resultant.y, 1e-12 * scale);
      EXPECT_NEAR(back.xx, m.xx, 1e-12 * scale);
      EXPECT_NEAR(back.xy, m.xy, 1e-12 * scale);
      EXPECT_NEAR(back.yx, m.yx, 1e-12 * scale);
      EXPECT_NEAR(back.yy, m.yy, 1e-12 * scale);
    }
  }
  // A force along a segment: ∫ q ds n at the segment's load centre.
  ForceMoments along;
  along.add_along({0.0, 0.0}, {2.0, 0.0}, 0.0, 3.0, {0.0, 1.0});  // triangle load: 3 N, centre at x = 4/3
  EXPECT_NEAR(along.resultant.y, 3.0, 1e-15);
  EXPECT_NEAR(along.xy, 3.0 * 4.0 / 3.0, 1e-15);
  EXPECT_THROW(distribute_to_vertices(Polygon{{0, 0}, {1, 1}, {2, 2}}, along), std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::coupling
