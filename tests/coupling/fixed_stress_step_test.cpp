// The flow half of the fixed-stress step (coupling/fixed_stress_step.hpp): the skeleton's
// volumes, storage and stabilisation per element from the blocks over it, and the heads the
// step folds its terms into, against hand-computed values (exact identities: round-off, 1e-14
// relative), and the undrained limit of a step through the Darcy solver.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coupling/fixed_stress_step.hpp"
#include "coupling/porosity.hpp"
#include "hydro/darcy_solver.hpp"
#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Polygon;

// Two unit squares side by side, each split into two triangles, under two blocks that cover
// one square each: every element lies wholly in one block.
struct TwoSquares {
  mesh::TriangleMesh mesh = testing::make_grid_mesh({0.0, 1.0, 2.0}, {0.0, 1.0});
  std::vector<Polygon> blocks{Polygon{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}},
                              Polygon{{1.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 1.0}}};
  FixedStressSettings settings{{1.0e-10, 3.0e-10}, {1.0, 0.5}, {8.0e8, 2.0e9}, 4.5e-10, 9810.0};
};

// ζ_e = α_b ε_v,b, S_e = ρ_w g S_b and β_e = ρ_w g α_b²/K_b in each element of block b; an
// element's open area adds its share to ζ and its water's c_w to S.
TEST(FixedStressStep, SkeletonVolumesAreEachBlocksShareOfItsStrainAndStorage) {
  TwoSquares m;
  const PorosityMapper mapper(m.mesh.nodes, m.mesh.triangles);
  BlockPieces pieces;
  (void)mapper.compute(m.blocks, 0.0, &pieces);
  const std::vector<double> strain{-2.0e-4, 3.0e-4};
  std::vector<double> open(4, 0.0);
  open[3] = 0.1;  // a tenth of element 3's area open (the blocks as given cover it: a stand-in)
  const SkeletonVolumes v =
      compute_skeleton_volumes(m.settings, mapper.element_areas(), pieces, strain, open, nullptr, {});
  for (int e = 0; e < 4; ++e) {
    const int b = mesh::triangle_centroid(m.mesh, e).x < 1.0 ? 0 : 1;
    const double share_open = open[e] / mapper.element_areas()[e];
    const double alpha = m.settings.biot[b];
    const double zeta = alpha * strain[b] + share_open;
    const double storage = 9810.0 * (m.settings.storage[b] + share_open * 4.5e-10);
    const double beta = 9810.0 * alpha * alpha / m.settings.drained_bulk[b];
    EXPECT_NEAR(v.zeta[e], zeta, 1e-14 * std::abs(zeta)) << e;
    EXPECT_NEAR(v.storage[e], storage, 1e-14 * storage) << e;
    EXPECT_NEAR(v.stabilisation[e], beta, 1e-14 * beta) << e;
  }
  EXPECT_THROW(compute_skeleton_volumes(m.settings, mapper.element_areas(), pieces, std::vector<double>{-2.0e-4}, open, nullptr, {}),
               std::invalid_argument);
}

// h̃_i = Σ_e (A_e/3)(S_e h^n_i + β_e h^{k−1}_i − Δζ_e) / Σ_e (A_e/3)(S_e + β_e), and c_e =
// (S_e + β_e)/Δt, on two triangles sharing an edge: hand-computed, to round-off.
TEST(FixedStressStep, FoldedHeadsHoldTheStepsStorageStabilisationAndSkeletonChange) {
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {1, 3, 2}};
  const std::vector<double> areas{0.5, 1.5};
  SkeletonVolumes now{{1.0e-5, -2.0e-5}, {1.0e-6, 4.0e-6}, {2.0e-5, 1.0e-5}};
  const std::vector<double> zeta_start{0.0, 1.0e-5};
  const std::vector<double> h_n{1.0, 2.0, 3.0, 4.0}, h_last{1.5, 2.5, 2.0, 5.0};
  const double dt = 10.0;
  const StepHeads step = fold_step_heads(triangles, areas, now, zeta_start, dt, h_n, h_last);
  EXPECT_NEAR(step.storage_over_step[0], (1.0e-6 + 2.0e-5) / dt, 1e-20);
  EXPECT_NEAR(step.storage_over_step[1], (4.0e-6 + 1.0e-5) / dt, 1e-20);
  // Node 1, in both triangles.
  const double a0 = 0.5 / 3.0, a1 = 1.5 / 3.0;
  const double mass = a0 * (1.0e-6 + 2.0e-5) + a1 * (4.0e-6 + 1.0e-5);
  const double held = a0 * (1.0e-6 * 2.0 + 2.0e-5 * 2.5 - 1.0e-5) + a1 * (4.0e-6 * 2.0 + 1.0e-5 * 2.5 - (-3.0e-5));
  EXPECT_NEAR(step.heads[1], held / mass, 1e-14 * std::abs(held / mass));
  // Node 0, in triangle 0 only.
  const double only = (1.0e-6 * 1.0 + 2.0e-5 * 1.5 - 1.0e-5) / (1.0e-6 + 2.0e-5);
  EXPECT_NEAR(step.heads[0], only, 1e-14 * std::abs(only));
  // Nothing changed since the step began: the step's heads are the start's.
  const StepHeads still = fold_step_heads(triangles, areas, now, now.zeta, dt, h_n, h_n);
  for (std::size_t i = 0; i < h_n.size(); ++i) EXPECT_NEAR(still.heads[i], h_n[i], 1e-14 * h_n[i]) << i;
}

// The open gaps' secant (fixed_stress_step.hpp): on three triangles, s = the largest
// ζgap^{k−2}_e / max(|Δh̄_e|, τ (max h − min h)) of the elements whose gap closed shut, kept at its
// largest over the step's iterates and given to every element that holds or held a gap; gaps
// that only narrow or open give none. Hand-computed, to round-off.
TEST(FixedStressStep, TheGapsSecantIsTheLargestOfTheGapsClosedShutGivenWhereAGapIsOrWas) {
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}};
  const std::vector<double> areas{0.5, 1.0, 2.0};
  const double tau = 1.0e-4;
  // The step's start: a gap in elements 0 and 1, none in 2; heads 0 to 10 m.
  const std::vector<double> h_n{0.0, 1.0, 2.0, 3.0, 10.0};
  GapSecant gaps = start_gap_secant(triangles, areas, std::vector<double>{0.01, 0.02, 0.0}, h_n);
  // Iterate 1 as the start (the step's first iteration): no change, no β.
  update_gap_secant(gaps, triangles, areas, std::vector<double>{0.01, 0.02, 0.0}, h_n, tau);
  for (double b : gaps.beta) EXPECT_EQ(b, 0.0);
  // Iterate 2: element 1's gap halves as its mean head rises 0.5 m, element 2's opens: neither
  // closed shut, no secant; element 2 now holds a gap.
  const std::vector<double> h_2{0.0, 1.0, 2.0, 4.5, 10.0};
  update_gap_secant(gaps, triangles, areas, std::vector<double>{0.01, 0.01, 0.002}, h_2, tau);
  EXPECT_EQ(gaps.largest, 0.0);
  for (double b : gaps.beta) EXPECT_EQ(b, 0.0);
  // Iterate 3: element 0's gap closes shut with its nodes' heads unchanged (the floor
  // τ × 10 m = 1e-3 m), element 1's shuts as its mean head rises 0.5 m (node 3 by 1.5 m).
  const std::vector<double> h_3{0.0, 1.0, 2.0, 6.0, 10.0};
  update_gap_secant(gaps, triangles, areas, std::vector<double>{0.0, 0.0, 0.002}, h_3, tau);
  const double element_0 = (0.01 / 0.5) / 1.0e-3;  // 20 per m
  const double element_1 = (0.01 / 1.0) / 0.5;     // 0.02 per m
  EXPECT_NEAR(gaps.largest, std::max(element_0, element_1), 1e-12 * element_0);
  for (std::size_t e = 0; e < 3; ++e) EXPECT_NEAR(gaps.beta[e], element_0, 1e-12 * element_0) << e;
  // Iterate 4: element 2's gap shuts too, over a head change of 4.5 m at its nodes (mean 1.5 m):
  // a smaller secant, and the step's largest is kept on all three, the shut ones included.
  const std::vector<double> h_4{0.0, 1.0, 2.0, 10.5, 10.0};
  update_gap_secant(gaps, triangles, areas, std::vector<double>{0.0, 0.0, 0.0}, h_4, tau);
  for (std::size_t e = 0; e < 3; ++e) EXPECT_NEAR(gaps.beta[e], element_0, 1e-12 * element_0) << e;
  // Heads all alike give no scale: a gap shut under them gives no secant.
  GapSecant flat = start_gap_secant(triangles, areas, std::vector<double>{0.01, 0.0, 0.0}, h_n);
  update_gap_secant(flat, triangles, areas, std::vector<double>{0.0, 0.0, 0.0}, std::vector<double>(5, 2.0), tau);
  EXPECT_EQ(flat.largest, 0.0);
  // A mesh with no gap in the step has no β.
  GapSecant none = start_gap_secant(triangles, areas, std::vector<double>(3, 0.0), h_n);
  update_gap_secant(none, triangles, areas, std::vector<double>(3, 0.0), h_2, tau);
  for (double b : none.beta) EXPECT_EQ(b, 0.0);
  EXPECT_THROW(update_gap_secant(gaps, triangles, areas, std::vector<double>{0.0, 0.0}, h_2, tau),
               std::invalid_argument);
}

// A node that no storing element touches cannot take the skeleton's change: refused, rather
// than the change silently lost.
TEST(FixedStressStep, RefusesASkeletonChangeWhereNothingStores) {
  const std::vector<std::array<int, 3>> triangles{{0, 1, 2}};
  const SkeletonVolumes none{{1.0e-5}, {0.0}, {0.0}};
  const std::vector<double> heads{0.0, 0.0, 0.0};
  EXPECT_THROW(fold_step_heads(triangles, std::vector<double>{0.5}, none, std::vector<double>{0.0}, 1.0, heads, heads),
               std::runtime_error);
  // No change there: the heads stay the start's, and the element has no storage.
  const StepHeads kept = fold_step_heads(triangles, std::vector<double>{0.5}, none, none.zeta, 1.0, heads, heads);
  EXPECT_EQ(kept.storage_over_step[0], 0.0);
}

// The undrained limit: a step a million times shorter than the diffusion time over an element
// leaves no time for water to move, so away from the fixed head S_s (h − h^n) + Δζ = 0 at a
// converged iterate (h^{k−1} = h): h − h^n = −Δζ/S_s, within 1e-6 relative (the flow over
// the step, K Δt/(S_s ℓ²) = 1e-6).
TEST(FixedStressStep, AVeryShortStepIsUndrained) {
  const std::vector<double> xs{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  mesh::TriangleMesh mesh = testing::make_grid_mesh(xs, {0.0, 1.0});
  mesh.boundary_names = {"left"};
  mesh.boundary_edges = {{{0, 11}, 0}};  // the edge x = 0 (nodes (0, 0) and (0, 1))
  hydro::DarcyProblem problem;
  problem.boundaries = {{"left", hydro::BoundaryKind::head, 0.0}};
  hydro::DarcySolver solver(mesh, problem);
  const std::size_t n = mesh.triangles.size();
  const double s_s = 1.0e-4;                    // 1/m
  const double k = 1.0e-3 * 1.0e-12 / 9810.0;   // K = k ρ g/μ = 1e-12 m/s
  const double dt = 1.0e-6 * s_s * 1.0 / 1.0e-12;  // K Δt/(S_s ℓ²) = 1e-6
  SkeletonVolumes now{std::vector<double>(n, -1.0e-6), std::vector<double>(n, s_s), std::vector<double>(n, 0.0)};
  const std::vector<double> zeta_start(n, 0.0), h_n(mesh.nodes.size(), 0.0);
  const StepHeads step = fold_step_heads(mesh.triangles, std::vector<double>(n, 0.5), now, zeta_start, dt, h_n, h_n);
  const hydro::FlowSolution flow =
      solver.solve_step(std::vector<double>(n, k), step.storage_over_step, hydro::MassMatrix::lumped, step.heads);
  const double undrained = 1.0e-6 / s_s;  // −Δζ/S_s = 0.01 m
  for (int i = 0; i < mesh.node_count(); ++i)
    if (mesh.nodes[i].x >= 5.0) {
      EXPECT_NEAR(flow.head[i], undrained, 1e-6 * undrained) << i;
    }
}

TEST(FixedStressStep, VolumetricStrainIsTheTraceInThePlane) {
  const std::vector<std::array<double, 3>> strains{{1.0e-4, -3.0e-4, 5.0e-4}};
  EXPECT_DOUBLE_EQ(volumetric_strains(strains)[0], -2.0e-4);
}

}  // namespace
}  // namespace hydrodda::coupling
