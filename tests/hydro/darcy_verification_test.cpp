// Verification of the P1 Darcy solver against exact solutions (DESIGN.md §2.2).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "flow_test_meshes.hpp"
#include "hydro/darcy_solver.hpp"
#include "hydro/element_pressure.hpp"
#include "hydro/region_flow.hpp"

namespace hydrodda::hydro {
namespace {

constexpr double kBalance = 1e-10;  // mass balance, relative, every run (requirement 4)

DarcyProblem make_problem(std::vector<BoundaryCondition> conditions,
                          PressureConvention convention = PressureConvention::overpressure) {
  DarcyProblem p;
  p.boundaries = std::move(conditions);
  p.pressure = convention;
  return p;
}

std::vector<int> all_triangles(const mesh::TriangleMesh& m) {
  std::vector<int> t(m.triangles.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = static_cast<int>(i);
  return t;
}

// 1. Uniform k, h = 3 − x on [0, 2] × [0, 1] (h = 3 left, 1 right, no flow top and bottom):
// P1 holds linear functions exactly, so heads are exact to round-off on any mesh;
// q = (K, 0), and the left boundary takes in K × 1 m² /s per metre.
TEST(DarcyVerification, LinearHeadIsExactOnUnstructuredMesh) {
  const auto m = testing::make_rectangle_mesh(2.0, 1.0, 0.05);
  DarcySolver solver(m, make_problem({{"left", BoundaryKind::head, 3.0}, {"right", BoundaryKind::head, 1.0}}));
  const double k = 1e-12;
  const Fluid fluid;
  const double conductivity = k * fluid.conductivity_per_permeability();
  const auto s = solver.solve(std::vector<double>(m.triangles.size(), k));
  for (int v = 0; v < m.node_count(); ++v) ASSERT_NEAR(s.head[v], 3.0 - m.nodes[v].x, 1e-10);
  for (const auto& q : s.flux) {
    ASSERT_NEAR(q.x / conductivity, 1.0, 1e-10);
    ASSERT_NEAR(q.y / conductivity, 0.0, 1e-10);
  }
  EXPECT_NEAR(s.boundary_flow("left") / (-conductivity), 1.0, 1e-10);
  EXPECT_NEAR(s.boundary_flow("right") / conductivity, 1.0, 1e-10);
  EXPECT_EQ(s.boundary_flow("top"), 0.0);
  EXPECT_LE(s.balance_error, kBalance);
  // Over-pressure convention: h_ref = min fixed head = 1, p = ρ g (h − 1).
  EXPECT_EQ(s.reference_head, 1.0);
  for (int v = 0; v < m.node_count(); ++v)
    ASSERT_NEAR(s.pressure[v], fluid.unit_weight() * (2.0 - m.nodes[v].x), 1e-10 * fluid.unit_weight());
  // Effective conductivity of the whole block equals K (uniform medium).
  const auto r = compute_region_flow(m, s, all_triangles(m), geometry::Point{1, 0});
  EXPECT_NEAR(r.effective_conductivity / conductivity, 1.0, 1e-10);
  EXPECT_NEAR(r.flow / conductivity, 1.0, 1e-10);  // Q = K Δh/L × W = K × 1 × 1
  // Centroid pressure = p at the centroid of the linear field: ρ g (2 − x_c).
  const auto pc = compute_centroid_pressure(m, s);
  for (int t = 0; t < m.triangle_count(); ++t)
    ASSERT_NEAR(pc[t], fluid.unit_weight() * (2.0 - mesh::triangle_centroid(m, t).x), 1e-10 * fluid.unit_weight());
  // Without a direction, d follows the mean flux: (1, 0) here, and the same answers.
  const auto d = compute_region_flow(m, s, all_triangles(m));
  EXPECT_NEAR(d.direction.x, 1.0, 1e-10);
  EXPECT_NEAR(d.direction.y, 0.0, 1e-10);
  EXPECT_NEAR(d.effective_conductivity / conductivity, 1.0, 1e-10);
  EXPECT_NEAR(d.length, 2.0, 1e-12);
  EXPECT_NEAR(d.width, 1.0, 1e-12);
}

// Anisotropic diagonal tensor k = diag(kxx, kyy): with h = 3 − x the flux is (Kxx, 0).
TEST(DarcyVerification, TensorPermeabilityScalesFluxAlongGradient) {
  const auto m = testing::make_rectangle_mesh(2.0, 1.0, 0.1);
  DarcySolver solver(m, make_problem({{"left", BoundaryKind::head, 3.0}, {"right", BoundaryKind::head, 1.0}}));
  const PermeabilityTensor k{2e-12, 0.0, 7e-12};
  const double kxx = k.xx * Fluid{}.conductivity_per_permeability();
  const auto s = solver.solve(std::vector<PermeabilityTensor>(m.triangles.size(), k));
  for (int v = 0; v < m.node_count(); ++v) ASSERT_NEAR(s.head[v], 3.0 - m.nodes[v].x, 1e-10);
  EXPECT_NEAR(s.boundary_flow("left") / (-kxx), 1.0, 1e-10);
  EXPECT_LE(s.balance_error, kBalance);
}

// Flux boundary: q·n = −q0 on the left (inflow), h = 0 on the right ⇒ h = (q0/K)(L − x).
TEST(DarcyVerification, FixedFluxGivesLinearHead) {
  const auto m = testing::make_rectangle_mesh(2.0, 1.0, 0.1);
  const double q0 = 1e-6, k = 1e-12;
  const double conductivity = k * Fluid{}.conductivity_per_permeability();
  DarcySolver solver(m, make_problem({{"left", BoundaryKind::flux, -q0}, {"right", BoundaryKind::head, 0.0}}));
  const auto s = solver.solve(std::vector<double>(m.triangles.size(), k));
  for (int v = 0; v < m.node_count(); ++v)
    ASSERT_NEAR(s.head[v], q0 / conductivity * (2.0 - m.nodes[v].x), 1e-10 * q0 / conductivity);
  EXPECT_NEAR(s.boundary_flow("left"), -q0, 1e-12 * q0);
  EXPECT_NEAR(s.boundary_flow("right"), q0, 1e-10 * q0);
  EXPECT_LE(s.balance_error, kBalance);
}

// Fixed pressure, both conventions. Over-pressure: h = h_ref + p/(ρg) with h_ref = 2 (the
// only head); hydrostatic: h = z + p/(ρg) at each node, p = ρ g (h − z) everywhere.
TEST(DarcyVerification, PressureConventions) {
  const auto m = testing::make_rectangle_mesh(2.0, 1.0, 0.1);
  const Fluid fluid;
  const double p_right = 0.5 * fluid.unit_weight();
  std::vector<double> k(m.triangles.size(), 1e-13);
  {
    DarcySolver solver(m, make_problem({{"left", BoundaryKind::head, 2.0}, {"right", BoundaryKind::pressure, p_right}}));
    const auto s = solver.solve(k);
    // right head 2.5, left 2: h = 2 + 0.25 x exactly.
    for (int v = 0; v < m.node_count(); ++v) ASSERT_NEAR(s.head[v], 2.0 + 0.25 * m.nodes[v].x, 1e-10);
    EXPECT_LE(s.balance_error, kBalance);
  }
  {
    // Hydrostatic: p = P on the top (z = 1) fixes h = 1 + P/(ρg) there; h = 0 on the bottom
    // and no flow on the sides give h = (1 + P/(ρg)) z exactly, and p = ρ g (h − z).
    DarcySolver solver(m, make_problem({{"bottom", BoundaryKind::head, 0.0}, {"top", BoundaryKind::pressure, p_right}},
                                       PressureConvention::hydrostatic));
    const auto s = solver.solve(k);
    for (int v = 0; v < m.node_count(); ++v) {
      const double z = m.nodes[v].y;
      ASSERT_NEAR(s.head[v], 1.5 * z, 1e-10);
      ASSERT_NEAR(s.pressure[v], fluid.unit_weight() * 0.5 * z, 1e-10 * fluid.unit_weight());
    }
    EXPECT_LE(s.balance_error, kBalance);
  }
}

// 2. Layers. Series (layers across the flow, widths L_i): Q = Δh W / Σ (L_i / K_i),
// K_eff = L / Σ (L_i / K_i) (harmonic mean). Parallel (layers along the flow, widths w_i):
// Q = Δh / L Σ K_i w_i, K_eff = Σ K_i w_i / W (arithmetic mean). Exact for P1 when the layer
// interfaces are mesh lines, so the tolerance is 1e-8 relative for contrasts (largest k over
// smallest) up to 1e6.
class LayeredMedium : public ::testing::TestWithParam<double> {};

TEST_P(LayeredMedium, SeriesGivesHarmonicMean) {
  const double contrast = GetParam();
  mesh::MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.05;
  request.regions = {{"a", {{0.3, 0}, {0.55, 0}, {0.55, 1}, {0.3, 1}}},
                     {"b", {{0.55, 0}, {0.8, 0}, {0.8, 1}, {0.55, 1}}}};
  const auto m = mesh::generate_mesh(request);
  const double k0 = 1e-12, ka = k0 * contrast, kb = k0 * std::sqrt(contrast);
  std::vector<double> k(m.triangles.size(), k0);
  for (int t : mesh::select_region(m, "a")) k[t] = ka;
  for (int t : mesh::select_region(m, "b")) k[t] = kb;
  DarcySolver solver(m, make_problem({{"left", BoundaryKind::head, 1.0}, {"right", BoundaryKind::head, 0.0}}));
  const auto s = solver.solve(k);
  const double f = Fluid{}.conductivity_per_permeability();
  const double harmonic = 1.0 / (0.5 / (k0 * f) + 0.25 / (ka * f) + 0.25 / (kb * f));
  EXPECT_NEAR(-s.boundary_flow("left") / harmonic, 1.0, 1e-8);
  EXPECT_NEAR(s.boundary_flow("right") / harmonic, 1.0, 1e-8);
  EXPECT_LE(s.balance_error, kBalance);
  const auto r = compute_region_flow(m, s, all_triangles(m), geometry::Point{1, 0});
  EXPECT_NEAR(r.effective_conductivity / harmonic, 1.0, 1e-8);
}

TEST_P(LayeredMedium, ParallelGivesArithmeticMean) {
  const double contrast = GetParam();
  mesh::MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.05;
  request.regions = {{"a", {{0, 0.2}, {1, 0.2}, {1, 0.3}, {0, 0.3}}},
                     {"b", {{0, 0.6}, {1, 0.6}, {1, 0.9}, {0, 0.9}}}};
  const auto m = mesh::generate_mesh(request);
  const double k0 = 1e-15, ka = k0 * contrast, kb = k0 * std::sqrt(contrast);
  std::vector<double> k(m.triangles.size(), k0);
  for (int t : mesh::select_region(m, "a")) k[t] = ka;
  for (int t : mesh::select_region(m, "b")) k[t] = kb;
  DarcySolver solver(m, make_problem({{"left", BoundaryKind::head, 1.0}, {"right", BoundaryKind::head, 0.0}}));
  const auto s = solver.solve(k);
  const double f = Fluid{}.conductivity_per_permeability();
  const double arithmetic = f * (0.6 * k0 + 0.1 * ka + 0.3 * kb);
  EXPECT_NEAR(-s.boundary_flow("left") / arithmetic, 1.0, 1e-8);
  EXPECT_NEAR(s.boundary_flow("right") / arithmetic, 1.0, 1e-8);
  EXPECT_LE(s.balance_error, kBalance);
  const auto r = compute_region_flow(m, s, all_triangles(m), geometry::Point{1, 0});
  EXPECT_NEAR(r.effective_conductivity / arithmetic, 1.0, 1e-8);
  // The region "a" alone: a uniform strip carrying K_a Δh/L × width 0.1.
  const auto ra = compute_region_flow(m, s, mesh::select_region(m, "a"), geometry::Point{1, 0});
  EXPECT_NEAR(ra.effective_conductivity / (ka * f), 1.0, 1e-8);
  EXPECT_NEAR(ra.flow / (ka * f * 0.1), 1.0, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Contrasts, LayeredMedium, ::testing::Values(1.0, 1e2, 1e4, 1e6));

// 3. Thiem: h(r) = h1 + (h2 − h1) ln(r/r1) / ln(r2/r1) between circles r1 and r2, and the
// radial flow Q = 2π K (h1 − h2) / ln(r2/r1). P1 converges at second order in L2:
// ‖h − h_h‖ ∝ size², so halving the size divides the error by 4 (rate 2 ± 0.15).
double compute_l2_error(const mesh::TriangleMesh& m, const std::vector<double>& head,
                        double r1, double r2, double h1, double h2) {
  // 7-point degree-5 rule on the triangle (Strang & Fix / Dunavant): barycentric points, weights.
  const double a1 = 0.0597158717, b1 = 0.4701420641, a2 = 0.7974269853, b2 = 0.1012865073;
  const std::array<std::array<double, 4>, 7> rule{{{1.0 / 3, 1.0 / 3, 1.0 / 3, 0.225},
                                                   {a1, b1, b1, 0.1323941527},
                                                   {b1, a1, b1, 0.1323941527},
                                                   {b1, b1, a1, 0.1323941527},
                                                   {a2, b2, b2, 0.1259391805},
                                                   {b2, a2, b2, 0.1259391805},
                                                   {b2, b2, a2, 0.1259391805}}};
  double sum = 0.0;
  for (int t = 0; t < m.triangle_count(); ++t) {
    const auto& tri = m.triangles[t];
    const double area = mesh::triangle_area(m, t);
    for (const auto& q : rule) {
      const geometry::Point p = q[0] * m.nodes[tri[0]] + q[1] * m.nodes[tri[1]] + q[2] * m.nodes[tri[2]];
      const double hh = q[0] * head[tri[0]] + q[1] * head[tri[1]] + q[2] * head[tri[2]];
      const double exact = h1 + (h2 - h1) * std::log(geometry::norm(p) / r1) / std::log(r2 / r1);
      sum += q[3] * area * (hh - exact) * (hh - exact);
    }
  }
  return std::sqrt(sum);
}

TEST(DarcyVerification, ThiemRadialFlowConvergesAtSecondOrder) {
  const double r1 = 0.1, r2 = 1.0, h1 = 10.0, h2 = 2.0, k = 1e-12;
  const double conductivity = k * Fluid{}.conductivity_per_permeability();
  std::vector<double> errors;
  for (int level = 0; level < 4; ++level) {
    const int nr = 8 << level, nt = 24 << level;
    const auto m = testing::make_annulus_mesh(r1, r2, nr, nt);
    DarcySolver solver(m, make_problem({{"inner", BoundaryKind::head, h1}, {"outer", BoundaryKind::head, h2}}));
    const auto s = solver.solve(std::vector<double>(m.triangles.size(), k));
    EXPECT_LE(s.balance_error, kBalance);
    errors.push_back(compute_l2_error(m, s.head, r1, r2, h1, h2));
    if (level == 3) {  // the flow itself converges too (1% at this resolution)
      const double q = 2 * std::numbers::pi * conductivity * (h1 - h2) / std::log(r2 / r1);
      EXPECT_NEAR(s.boundary_flow("outer") / q, 1.0, 1e-2);
    }
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double rate = std::log2(errors[i - 1] / errors[i]);
    EXPECT_NEAR(rate, 2.0, 0.15) << "refinement " << i << ": errors " << errors[i - 1] << " → " << errors[i];
  }
}

// 5. Thin strips (width 0.004, like open fractures) 1e5 times more permeable than the matrix,
// along the flow: h = 1 − x is exact, and the inflow is (3 w k_f + (1 − 3w) k_m) ρ g / μ.
// A second solve on the same solver with k_f doubled checks the numeric-refactor path.
TEST(DarcyVerification, ThinPermeableStripsSolveToRoundOff) {
  const double w = 0.004, km = 1e-14, kf = 1e-9;
  mesh::MeshRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.size = 0.04;
  request.fracture_size = 0.002;
  request.refine_distance = 0.1;
  for (double y : {0.25, 0.5, 0.75}) {
    request.refinement_lines.push_back({{0, y}, {1, y}});
    request.regions.push_back({"strip", {{0, y - w / 2}, {1, y - w / 2}, {1, y + w / 2}, {0, y + w / 2}}});
  }
  const auto m = mesh::generate_mesh(request);
  DarcySolver solver(m, make_problem({{"left", BoundaryKind::head, 1.0}, {"right", BoundaryKind::head, 0.0}}));
  const auto strip = mesh::select_region(m, "strip");
  const double f = Fluid{}.conductivity_per_permeability();
  for (double kf_now : {kf, 2 * kf}) {
    std::vector<double> k(m.triangles.size(), km);
    for (int t : strip) k[t] = kf_now;
    const auto s = solver.solve(k);
    for (int v = 0; v < m.node_count(); ++v) ASSERT_NEAR(s.head[v], 1.0 - m.nodes[v].x, 1e-10);
    const double exact = (3 * w * kf_now + (1 - 3 * w) * km) * f;
    EXPECT_NEAR(-s.boundary_flow("left") / exact, 1.0, 1e-8);
    EXPECT_NEAR(s.boundary_flow("right") / exact, 1.0, 1e-8);
    EXPECT_LE(s.balance_error, kBalance);
  }
}

}  // namespace
}  // namespace hydrodda::hydro
