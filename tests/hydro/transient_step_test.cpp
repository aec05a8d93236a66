// DarcySolver::solve_step, a backward-Euler step of S_s ∂h/∂t − ∇·(K ∇h) = 0:
// (A + Σ_e c_e M_e) h = f + Σ_e c_e M_e h_old, c_e = S_s,e/Δt. Checked against exact identities
// (the water each node stores balances the boundary flows to round-off; a step from the steady
// heads stays there; the kept factor gives the fresh one's heads), the discrete maximum
// principle of the lumped mass matrix (Thomée, Galerkin Finite Element Methods for Parabolic
// Problems, 2nd ed. 2006, ch. 15: with M lumped and a mesh of non-obtuse triangles the heads
// stay within the range of the initial and boundary values; the consistent M overshoots at a
// step in head when Δt is small against the elements), and Carslaw & Jaeger's series for 1D
// diffusion, within 1% of the head change.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "flow_test_meshes.hpp"
#include "hydro/darcy_solver.hpp"

namespace hydrodda::hydro {
namespace {

// A structured strip [0, length] × [0, width], `cells` squares along x cut by one diagonal each
// (right triangles: non-obtuse). Boundaries left, right, bottom, top.
mesh::TriangleMesh make_strip(double length, double width, int cells) {
  mesh::TriangleMesh m;
  m.region_names = {"domain"};
  m.boundary_names = {"left", "right", "bottom", "top"};
  const double dx = length / cells;
  for (int i = 0; i <= cells; ++i) {
    m.nodes.push_back({i * dx, 0.0});
    m.nodes.push_back({i * dx, width});
  }
  for (int i = 0; i < cells; ++i) {
    const int a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
    m.region.insert(m.region.end(), {0, 0});
    m.boundary_edges.push_back({{a, b}, 2});
    m.boundary_edges.push_back({{c, d}, 3});
  }
  m.boundary_edges.push_back({{1, 0}, 0});
  m.boundary_edges.push_back({{2 * cells, 2 * cells + 1}, 1});
  return m;
}

// Carslaw & Jaeger (1959) §3.3: the strip 0 < x < L at h = 0, its end x = 0 raised to H at
// t = 0, x = L closed: h/H = 1 − Σ_{n≥0} 4/((2n+1)π) sin((2n+1)πx/(2L)) exp(−(2n+1)²π²ct/(4L²)).
double series_head(double x, double t, double c, double length) {
  double sum = 0.0;
  for (int n = 0; n < 2000; ++n) {
    const double m = 2.0 * n + 1.0;
    sum += 4.0 / (m * std::numbers::pi) * std::sin(m * std::numbers::pi * x / (2.0 * length)) *
           std::exp(-m * m * std::numbers::pi * std::numbers::pi * c * t / (4.0 * length * length));
  }
  return 1.0 - sum;
}

DarcyProblem head_on(const std::string& boundary, double head) {
  DarcyProblem p;
  p.boundaries = {{boundary, BoundaryKind::head, head}};
  return p;
}

// k = 1e-13 m², μ = 1e-3 Pa s: K = 9.81e-7 m/s; S_s = 9.81e-6 1/m: c = K/S_s = 0.1 m²/s.
constexpr double kPermeability = 1e-13;
constexpr double kSpecificStorage = 9.81e-6;
constexpr double kDiffusivity = 0.1;

// The heads after stepping from h = 0 with the left end at 1 m by `steps` steps of `dt`.
std::vector<double> step_strip(const mesh::TriangleMesh& m, MassMatrix kind, double dt, int steps) {
  DarcySolver solver(m, head_on("left", 1.0));
  const std::vector<double> k(m.triangles.size(), kPermeability);
  const std::vector<double> c(m.triangles.size(), kSpecificStorage / dt);
  std::vector<double> h(m.nodes.size(), 0.0);
  for (int n = 0; n < steps; ++n) h = solver.solve_step(k, c, kind, h).head;
  return h;
}

TEST(TransientStep, TheWaterStoredBalancesTheBoundaryFlows) {
  const mesh::TriangleMesh m = testing::make_rectangle_mesh(2.0, 1.0, 0.2);
  DarcyProblem problem;
  problem.boundaries = {{"left", BoundaryKind::head, 3.0}, {"right", BoundaryKind::head, 1.0}};
  DarcySolver solver(m, problem);
  std::vector<double> k(m.triangles.size()), c(m.triangles.size());
  for (int t = 0; t < m.triangle_count(); ++t) {
    const geometry::Point centre = mesh::triangle_centroid(m, t);
    k[t] = centre.y < 0.5 ? 1e-12 : 4e-12;
    c[t] = centre.x < 1.0 ? 2e-4 : 7e-5;
  }
  const std::vector<double> previous(m.nodes.size(), 1.5);
  for (const MassMatrix kind : {MassMatrix::lumped, MassMatrix::consistent}) {
    const FlowSolution step = solver.solve_step(k, c, kind, previous);
    // Σ_i (c M (h − h_old))_i = Σ_e c_e ∫_e (h − h_old), the mass matrix assembled on its own.
    double stored = 0.0;
    for (int t = 0; t < m.triangle_count(); ++t) {
      const auto& tri = m.triangles[t];
      const double area = std::abs(mesh::triangle_area(m, t));
      const auto mass = compute_element_mass_matrix(area, kind);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) stored += c[t] * mass[i][j] * (step.head[tri[j]] - previous[tri[j]]);
    }
    EXPECT_NEAR(step.storage_rate, stored, 1e-12 * std::abs(stored));
    double outflow = 0.0;
    for (const BoundaryFlow& b : step.boundary_flows) outflow += b.flow;
    EXPECT_NEAR(outflow + step.storage_rate, 0.0, 1e-11 * std::abs(stored));
    EXPECT_LE(step.balance_error, 1e-11);
    EXPECT_GT(std::abs(stored), 1e-6);  // the step stores water: the balance is not that of a steady flow
  }
}

TEST(TransientStep, AStepFromTheSteadyHeadsStaysThereAndASteadySolveAfterIsUnchanged) {
  const mesh::TriangleMesh m = testing::make_rectangle_mesh(2.0, 1.0, 0.2);
  DarcyProblem problem;
  problem.boundaries = {{"left", BoundaryKind::head, 3.0}, {"right", BoundaryKind::head, 1.0}};
  const std::vector<double> k(m.triangles.size(), 1e-12);
  DarcySolver fresh(m, problem);
  const FlowSolution steady = fresh.solve(k);
  DarcySolver solver(m, problem);
  const FlowSolution step = solver.solve_step(k, std::vector<double>(m.triangles.size(), 1e-2), MassMatrix::lumped, steady.head);
  for (int v = 0; v < m.node_count(); ++v) ASSERT_NEAR(step.head[v], steady.head[v], 1e-12);
  EXPECT_NEAR(step.storage_rate, 0.0, 1e-12 * std::abs(steady.boundary_flow("left")));
  // The storage is dropped by the next assembly: a steady solve after a step is a steady solve,
  // bit for bit.
  const FlowSolution again = solver.solve(k);
  EXPECT_EQ(again.head, steady.head);
  EXPECT_EQ(again.balance_error, steady.balance_error);
  EXPECT_EQ(again.storage_rate, 0.0);
}

TEST(TransientStep, TheFactorIsKeptWhileTheStepIsTheSame) {
  const mesh::TriangleMesh m = make_strip(10.0, 0.5, 50);
  DarcySolver solver(m, head_on("left", 1.0));
  const std::vector<double> k(m.triangles.size(), kPermeability);
  const std::vector<double> c(m.triangles.size(), kSpecificStorage / 2.0);
  const std::vector<double> zero(m.nodes.size(), 0.0);
  const FlowSolution first = solver.solve_step(k, c, MassMatrix::lumped, zero);
  const FlowSolution second = solver.solve_step(k, c, MassMatrix::lumped, first.head);
  EXPECT_TRUE(first.factorised);
  EXPECT_FALSE(second.factorised);
  DarcySolver fresh(m, head_on("left", 1.0));
  fresh.solve_step(k, c, MassMatrix::lumped, zero);
  const std::vector<double> longer(m.triangles.size(), kSpecificStorage / 3.0);
  const FlowSolution refactored = solver.solve_step(k, longer, MassMatrix::lumped, second.head);
  EXPECT_TRUE(refactored.factorised);  // a new Δt: a new matrix
  // Same matrix, same right-hand side: the kept factor's heads are the fresh factor's.
  DarcySolver other(m, head_on("left", 1.0));
  const FlowSolution other_second = other.solve_step(k, c, MassMatrix::lumped, first.head);
  for (int v = 0; v < m.node_count(); ++v) EXPECT_NEAR(second.head[v], other_second.head[v], 1e-14);
}

// The first step after a step in head, Δt = 0.01 s against elements 0.2 m long (c Δt/dx² = 0.025):
// the lumped heads stay in [0, 1]; the consistent ones dip below 0 ahead of the front.
TEST(TransientStep, LumpedStorageKeepsTheHeadsWithinTheirBoundsWhereConsistentOvershoots) {
  const mesh::TriangleMesh m = make_strip(10.0, 0.5, 50);
  const std::vector<double> lumped = step_strip(m, MassMatrix::lumped, 0.01, 1);
  const std::vector<double> consistent = step_strip(m, MassMatrix::consistent, 0.01, 1);
  EXPECT_GE(*std::min_element(lumped.begin(), lumped.end()), 0.0);
  EXPECT_LE(*std::max_element(lumped.begin(), lumped.end()), 1.0);
  EXPECT_LT(*std::min_element(consistent.begin(), consistent.end()), -1e-3);
}

// Against the series at t = 20 and 100 s (t c/L² = 0.02, 0.1), steps of 0.1 s, 200 elements:
// within 1% of the head change for both mass matrices (measured: docs/flow.md, "Transient flow").
TEST(TransientStep, OneDimensionalDiffusionFollowsTheSeries) {
  const mesh::TriangleMesh m = make_strip(10.0, 0.5, 200);
  for (const MassMatrix kind : {MassMatrix::lumped, MassMatrix::consistent})
    for (const int steps : {200, 1000}) {
      const std::vector<double> h = step_strip(m, kind, 0.1, steps);
      double worst = 0.0;
      for (int v = 0; v < m.node_count(); ++v)
        worst = std::max(worst, std::abs(h[v] - series_head(m.nodes[v].x, 0.1 * steps, kDiffusivity, 10.0)));
      EXPECT_LT(worst, 0.01) << (kind == MassMatrix::lumped ? "lumped" : "consistent") << " at t = " << 0.1 * steps;
      std::printf("%s t = %g s: largest error %.3e of the head change\n",
                  kind == MassMatrix::lumped ? "lumped" : "consistent", 0.1 * steps, worst);
    }
}

}  // namespace
}  // namespace hydrodda::hydro
