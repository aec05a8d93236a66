// The fluid's stiffness within a coupling pass (coupling/pass_storage.hpp): the joints'
// compliance against the Barton–Bandis law it is the derivative of, the storage per element,
// the pseudo-time step's rule, and the identity that makes the stepped pass's fixed point the
// steady one.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <algorithm>

#include "coupling/pass_storage.hpp"
#include "hydro/darcy_solver.hpp"
#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

// C = da/dp = −da/dσ of a = a_r + V_m − σ V_m/(k_ni V_m + σ) (Bandis et al. 1983), taken at the
// aperture the law gives: against a central difference of the law (step 1e-4 σ, truncation
// error O(step²) ≈ 1e-8 relative), within 1e-6 relative, at 0.1 to 50 MPa.
TEST(PassStorage, JointComplianceIsTheBartonBandisDerivativeAtTheApertureItsStressGives) {
  const hydro::JointApertureLaw law{1.0e-5, 2.0e10, 5.0e-5};
  for (double sigma : {1.0e5, 1.0e6, 5.0e6, 2.0e7, 5.0e7}) {
    const double h = 1e-4 * sigma;
    const double derivative = -(law.closed(sigma + h) - law.closed(sigma - h)) / (2 * h);
    EXPECT_NEAR(joint_compliance(law, law.closed(sigma)), derivative, 1e-6 * derivative) << sigma;
  }
  // Open (a above a_r + V_m: no stress on the face): the initial stiffness's inverse.
  EXPECT_DOUBLE_EQ(joint_compliance(law, law.open(2.0e-5)), 1.0 / law.normal_stiffness);
  // A law with no closure does not deform: no compliance.
  EXPECT_EQ(joint_compliance(hydro::JointApertureLaw{1.0e-5, 0.0, 0.0}, 1.0e-5), 0.0);
}

// Without joints S_e = ρ_w g (s_m + f c_w) exactly (to round-off, 1e-15 relative).
TEST(PassStorage, MatrixAndOpenWaterStoreByTheirCompressibilities) {
  PseudoTimeSettings settings;
  settings.matrix_storage = {1.25e-10, 2.0e-10};
  settings.fluid_compressibility = 4.5e-10;
  settings.unit_weight = 9810.0;
  const std::vector<double> areas{0.5, 0.5}, open{0.0, 0.2};
  const std::vector<double> s = compute_pass_storage(settings, areas, open, nullptr, {});
  EXPECT_NEAR(s[0], 9810.0 * 1.25e-10, 1e-15 * s[0]);
  EXPECT_NEAR(s[1], 9810.0 * (2.0e-10 + 0.2 * 4.5e-10), 1e-15 * s[1]);
  settings.matrix_storage.pop_back();
  EXPECT_THROW(compute_pass_storage(settings, areas, open, nullptr, {}), std::invalid_argument);
}

// SER (Kelley & Keyes 1998 eq. 1.5): Δτ grows by the ratio of the last two residuals, at most
// doubling and at least halving a pass.
TEST(PassStorage, PseudoTimeStepFollowsTheResidualsRatioWithinItsBounds) {
  EXPECT_DOUBLE_EQ(next_pseudo_time_step(100.0, 1e-2, 8e-3), 125.0);
  EXPECT_DOUBLE_EQ(next_pseudo_time_step(100.0, 1e-2, 1e-4), 200.0);
  EXPECT_DOUBLE_EQ(next_pseudo_time_step(100.0, 1e-3, 1e-1), 50.0);
  EXPECT_DOUBLE_EQ(next_pseudo_time_step(100.0, 1e-3, 0.0), 200.0);
}

// The stepped pass's fixed point is the steady one: a backward-Euler step from the steady
// heads returns them (the storage term Σ c M (h − h_prev) vanishes there), whatever Δτ, to the
// solve's round-off (1e-9 m on heads of 10 m); from other heads, at a Δτ short against the
// diffusion time, it moves them only part-way (here more than 1 m short of the steady heads).
TEST(PassStorage, AStepFromTheSteadyHeadsReturnsThemWhateverThePseudoTimeStep) {
  mesh::TriangleMesh mesh = testing::make_rectangle_mesh(0.0, 0.0, 10.0, 4.0, 20, 8);
  mesh.boundary_names = {"left", "right"};
  for (const auto& e : mesh::find_boundary_edges(mesh.triangles)) {
    const double xa = mesh.nodes[e[0]].x, xb = mesh.nodes[e[1]].x;
    const int name = xa == 0.0 && xb == 0.0 ? 0 : (xa == 10.0 && xb == 10.0 ? 1 : mesh::BoundaryEdge::kUnnamed);
    mesh.boundary_edges.push_back({e, name});
  }
  hydro::DarcyProblem problem;
  problem.boundaries = {{"left", hydro::BoundaryKind::head, 10.0}, {"right", hydro::BoundaryKind::head, 0.0}};
  hydro::DarcySolver solver(mesh, problem);
  std::vector<double> k(mesh.triangle_count(), 1.0e-14);
  for (int t = 0; t < mesh.triangle_count(); t += 3) k[t] = 1.0e-12;  // not a linear head
  const std::vector<double> steady = solver.solve(k).head;
  const std::vector<double> flat(steady.size(), 5.0);
  for (double dtau : {1.0, 1.0e3, 1.0e6}) {
    const std::vector<double> storage(mesh.triangle_count(), 1.0e-6 / dtau);
    const std::vector<double> again = solver.solve_step(k, storage, hydro::MassMatrix::lumped, steady).head;
    for (std::size_t i = 0; i < steady.size(); ++i) EXPECT_NEAR(again[i], steady[i], 1e-9) << dtau;
  }
  // Δτ = 1 s against a diffusion time S L²/K ≈ 1e-6 × 100/1e-7 = 1,000 s across the strip.
  const std::vector<double> storage(mesh.triangle_count(), 1.0e-6 / 1.0);
  const std::vector<double> part_way = solver.solve_step(k, storage, hydro::MassMatrix::lumped, flat).head;
  double largest = 0.0;
  for (std::size_t i = 0; i < steady.size(); ++i) largest = std::max(largest, std::abs(part_way[i] - steady[i]));
  EXPECT_GT(largest, 1.0);
}

}  // namespace
}  // namespace hydrodda::coupling
