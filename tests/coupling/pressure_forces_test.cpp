#include "coupling/pressure_forces.hpp"

#include <gtest/gtest.h>

#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Polygon;

struct Resultant {
  Point force;
  double moment = 0.0;  // about the origin
};

Resultant sum_forces(const std::vector<Polygon>& blocks, const std::vector<std::vector<Point>>& forces) {
  Resultant r;
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (std::size_t v = 0; v < blocks[b].size(); ++v) {
      r.force += forces[b][v];
      r.moment += geometry::cross(blocks[b][v], forces[b][v]);
    }
  return r;
}

const std::vector<Polygon> kBlocks{
    {{0.1, 0.1}, {0.9, 0.2}, {0.7, 0.8}},
    {{1.0, 1.0}, {1.6, 1.05}, {1.9, 1.7}, {1.3, 1.4}, {1.05, 1.8}},  // non-convex
};

TEST(PressureForces, UniformPressureGivesNoNetForceOrMoment) {
  // ∮ p n ds = 0 and ∮ p (x × n) ds = 0 for constant p: 1e-12 of p × perimeter (× size).
  const double p = 7.5e6;
  for (const Polygon& block : kBlocks) {
    const std::vector<Polygon> one{block};
    const std::vector<std::vector<double>> pressure{std::vector<double>(block.size(), p)};
    const Resultant r = sum_forces(one, compute_edge_load_forces(one, pressure));
    double perimeter = 0.0;
    for (std::size_t i = 0; i < block.size(); ++i) perimeter += geometry::distance(block[i], block[(i + 1) % block.size()]);
    EXPECT_NEAR(r.force.x, 0.0, 1e-12 * p * perimeter);
    EXPECT_NEAR(r.force.y, 0.0, 1e-12 * p * perimeter);
    EXPECT_NEAR(r.moment, 0.0, 1e-12 * p * perimeter * 2.0);
  }
}

TEST(PressureForces, LinearPressureGivesExactBuoyancy) {
  // p = ρ g (h0 − y) sampled exactly at the vertices: the consistent loads integrate a linear
  // pressure exactly, so the resultant is Archimedes' ρ g A upward (1e-12 relative).
  const double rho_g = 1000.0 * 9.81;
  for (const Polygon& block : kBlocks) {
    std::vector<double> p;
    for (Point v : block) p.push_back(rho_g * (10.0 - v.y));
    const std::vector<Polygon> one{block};
    const Resultant r = sum_forces(one, compute_edge_load_forces(one, std::vector<std::vector<double>>{p}));
    const double buoyancy = rho_g * geometry::area(block);
    EXPECT_NEAR(r.force.y, buoyancy, 1e-12 * buoyancy);
    EXPECT_NEAR(r.force.x, 0.0, 1e-12 * buoyancy);
  }
}

TEST(PressureForces, HydrostaticFieldOnAMeshGivesBuoyancy) {
  // The coupling's path: nodal pressures ρ g (h0 − y) on a fine mesh, centroid pressures, each
  // vertex sampled from the element holding it. The sampling error is O(element size), so the
  // buoyancy ρ g A is met within 0.5% (DESIGN.md §2.3).
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 80, 80);
  const double rho_g = 1000.0 * 9.81;
  std::vector<double> element_pressure;
  for (const auto& t : mesh.triangles) {
    double p = 0.0;
    for (int n : t) p += rho_g * (10.0 - mesh.nodes[n].y);
    element_pressure.push_back(p / 3.0);
  }
  VertexPressureSampler sampler(mesh);
  const auto pressures = sampler.sample(kBlocks, element_pressure);
  const auto forces = compute_edge_load_forces(kBlocks, pressures);
  for (std::size_t b = 0; b < kBlocks.size(); ++b) {
    Point f{};
    for (Point v : forces[b]) f += v;
    const double buoyancy = rho_g * geometry::area(kBlocks[b]);
    EXPECT_NEAR(f.y, buoyancy, 0.005 * buoyancy) << "block " << b;
    EXPECT_NEAR(f.x, 0.0, 0.005 * buoyancy) << "block " << b;
  }
}

TEST(PressureForces, VertexOutsideTheMeshTakesTheNearestBoundaryElement) {
  // A block pushed 0.1 m out through the right side: its outside vertex takes the pressure of
  // the element that owns the boundary edge it faces (the one just inside at the same height).
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 8, 8);
  std::vector<double> element_pressure(mesh.triangles.size());
  for (std::size_t t = 0; t < element_pressure.size(); ++t) element_pressure[t] = 100.0 * t;
  const VertexPressureSampler sampler(mesh);
  const std::vector<Polygon> blocks{{{1.5, 0.6}, {2.1, 0.77}, {1.5, 0.9}}};
  const auto pressures = sampler.sample(blocks, element_pressure);
  const int inside = mesh::PointLocator(mesh).locate({2.0 - 1e-9, 0.77});
  ASSERT_GE(inside, 0);
  EXPECT_EQ(pressures[0][1], element_pressure[inside]);
  EXPECT_EQ(pressures[0][0], element_pressure[mesh::PointLocator(mesh).locate({1.5, 0.6})]);
}

}  // namespace
}  // namespace hydrodda::coupling
