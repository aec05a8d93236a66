// Verification 3 of the interface: parallel fractures of aperture w and spacing s. With the
// cubic law the effective permeability along them is w³/(12 s) (plus the matrix share) for
// fracture element sizes h from w/2 to 10 w, within 2%; Kozeny–Carman's result depends on h,
// which this test measures and prints (docs/coupling.md records it).
//
// Set-up: one period of the fracture set, [0, L] × [0, s] with the fracture's centre line at
// y = s/2 + 0.3 h (off the element rows, so elements are cut across), the two blocks below and
// above it shrunk to leave w; a structured mesh of h × h cells; h = 1 m head drop along x.
// k_eff = Q μ L / (ρ g s Δh), Q the outflow from the assembled system.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "coupling/local_aperture.hpp"
#include "coupling/permeability_model.hpp"
#include "coupling/porosity.hpp"
#include "hydro/darcy_solver.hpp"
#include "hydro/permeability_law.hpp"
#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Polygon;

struct Result {
  double cubic = 0.0;
  double kozeny_carman = 0.0;
};

Result effective_permeability(double w, double s, double h) {
  const int ny = static_cast<int>(std::lround(s / h));
  const int nx = 10;
  const double length = nx * h;
  auto mesh = testing::make_rectangle_mesh(0.0, 0.0, length, ny * h, nx, ny);
  mesh.boundary_names = {"left", "right"};
  for (const auto& e : mesh::find_boundary_edges(mesh.triangles)) {
    const auto a = mesh.nodes[e[0]], b = mesh.nodes[e[1]];
    int name = mesh::BoundaryEdge::kUnnamed;
    if (a.x == 0.0 && b.x == 0.0) name = 0;
    if (a.x == length && b.x == length) name = 1;
    mesh.boundary_edges.push_back({e, name});
  }
  const double height = ny * h;
  const double centre = 0.5 * height + 0.3 * h;
  const std::vector<Polygon> blocks{{{0, 0}, {length, 0}, {length, centre - w / 2}, {0, centre - w / 2}},
                                    {{0, centre + w / 2}, {length, centre + w / 2}, {length, height}, {0, height}}};
  const double phi_m = 0.1, grain = 1.2e-5, cap = 9.869e-11;
  const PorosityMapper mapper(mesh.nodes, mesh.triangles);
  const PorosityField porosity = mapper.compute(blocks, phi_m);
  std::vector<geometry::Point> centroids;
  for (int t = 0; t < mesh.triangle_count(); ++t) centroids.push_back(mesh::triangle_centroid(mesh, t));
  const Polygon domain{{0, 0}, {length, 0}, {length, height}, {0, height}};
  const auto apertures = compute_local_apertures(centroids, porosity.fracture_area, blocks, domain, 0.5 * height);
  const double k_matrix = hydro::kozeny_carman_permeability(phi_m, grain, cap);
  std::vector<double> k_cubic, k_kc;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const double fraction = porosity.fracture_area[t] / mapper.element_areas()[t];
    k_cubic.push_back(hydro::cubic_law_permeability(fraction, apertures[t], k_matrix));
    k_kc.push_back(hydro::kozeny_carman_permeability(porosity.porosity[t], grain, cap));
  }
  hydro::DarcyProblem problem;
  problem.boundaries = {{"left", hydro::BoundaryKind::head, 1.0}, {"right", hydro::BoundaryKind::head, 0.0}};
  hydro::DarcySolver solver(mesh, problem);
  const double per_k = problem.fluid.conductivity_per_permeability();
  const auto keff = [&](const std::vector<double>& k) {
    return solver.solve(k).boundary_flow("right") * length / (per_k * height * 1.0);
  };
  return {keff(k_cubic), keff(k_kc)};
}

TEST(CubicLaw, ParallelFracturesKeepTheirTransmissivity) {
  const double w = 1e-3, s = 40 * w;
  const double k_matrix = hydro::kozeny_carman_permeability(0.1, 1.2e-5, 9.869e-11);
  const double exact = w * w * w / (12 * s) + k_matrix * (1 - w / s);
  for (double h : {w / 2, w, 2 * w, 5 * w, 10 * w}) {
    const Result r = effective_permeability(w, s, h);
    std::printf("h = %4.1f w: cubic %.4e (%+.2f%%), Kozeny-Carman %.4e (%.2e of w^3/12s)\n", h / w, r.cubic,
                100 * (r.cubic / exact - 1), r.kozeny_carman, r.kozeny_carman / exact);
    EXPECT_NEAR(r.cubic, exact, 0.02 * exact) << "h = " << h / w << " w";
  }
}

// A matrix of grain size and porosity whose Kozeny–Carman permeability is 1.02e-7 m², a
// thousand times the default cap: the cubic law takes it as it is, in every element with no
// open area and as k_m; Kozeny–Carman caps it, and says so (matrix_capped).
TEST(PermeabilityModel, CubicLawMatrixIsNotCapped) {
  PermeabilityModel model;
  model.matrix_porosity = 0.3;
  model.grain_diameter = std::sqrt(1.02e-7 * 180.0 * 0.7 * 0.7 / (0.3 * 0.3 * 0.3));
  const double own = hydro::kozeny_carman_permeability(0.3, model.grain_diameter, INFINITY);
  ASSERT_NEAR(own, 1.02e-7, 1e-12);
  ASSERT_GT(own, 1000 * model.cap);
  model.law = PermeabilityLaw::cubic;
  EXPECT_EQ(model.matrix_permeability(), own);
  EXPECT_FALSE(model.matrix_capped());
  PorosityField intact;
  intact.porosity = {0.3, 0.3};
  intact.fracture_area = {0.0, 0.0};
  const std::vector<double> areas{1.0, 1.0}, apertures{0.0, 0.0};
  EXPECT_EQ(model.compute(intact, areas, apertures), (std::vector<double>{own, own}));
  model.law = PermeabilityLaw::kozeny_carman;
  EXPECT_EQ(model.matrix_permeability(), model.cap);
  EXPECT_TRUE(model.matrix_capped());
  EXPECT_EQ(model.compute(intact, areas), (std::vector<double>{model.cap, model.cap}));
}

}  // namespace
}  // namespace hydrodda::coupling
