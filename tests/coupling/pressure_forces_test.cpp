#include "coupling/pressure_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hydro/element_pressure.hpp"
#include "structured_mesh.hpp"
#include "mesh/point_locator.hpp"

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

double perimeter(const Polygon& block) {
  double sum = 0.0;
  for (std::size_t i = 0; i < block.size(); ++i) sum += geometry::distance(block[i], block[(i + 1) % block.size()]);
  return sum;
}

const std::vector<Polygon> kBlocks{
    {{0.1, 0.1}, {0.9, 0.2}, {0.7, 0.8}},
    {{1.0, 1.0}, {1.6, 1.05}, {1.9, 1.7}, {1.3, 1.4}, {1.05, 1.8}},  // non-convex
};

std::vector<double> nodal_values(const mesh::TriangleMesh& mesh, double (*field)(Point)) {
  std::vector<double> p;
  for (Point n : mesh.nodes) p.push_back(field(n));
  return p;
}

// A pressure far from linear (about 10 MPa, varying by some 40%).
double wavy_pressure(Point x) { return 1e7 * (1.0 + 0.3 * std::sin(3.0 * x.x + 1.0) * std::cos(2.0 * x.y) + 0.1 * x.x * x.y); }

TEST(PressureForces, UniformPressureGivesNoNetForceOrMoment) {
  // ∮ p n ds = 0 and ∮ p (x × n) ds = 0 for constant p: 1e-12 of p × perimeter (× size).
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 23, 19);
  const FacePressureLoads loads(mesh);
  const std::vector<double> p(mesh.nodes.size(), 7.5e6);
  for (const Polygon& block : kBlocks) {
    const std::vector<Polygon> one{block};
    const Resultant r = sum_forces(one, loads.compute(one, p, std::vector<double>{0.0}));
    EXPECT_NEAR(r.force.x, 0.0, 1e-12 * 7.5e6 * perimeter(block));
    EXPECT_NEAR(r.force.y, 0.0, 1e-12 * 7.5e6 * perimeter(block));
    EXPECT_NEAR(r.moment, 0.0, 1e-12 * 7.5e6 * perimeter(block) * 2.0);
  }
}

TEST(PressureForces, LinearPressureGivesExactBuoyancyOnAnyMesh) {
  // p = ρ g (10 − y) at the nodes: the P1 field is that linear pressure exactly, and the faces
  // integrate it exactly, so each block takes Archimedes' ρ g A upward, 1e-12 relative, on a
  // coarse mesh as on a fine one (the faces cross many elements and end inside them).
  const double rho_g = 1000.0 * 9.81;
  for (int cells : {3, 17, 80}) {
    const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, cells, cells);
    std::vector<double> p;
    for (Point n : mesh.nodes) p.push_back(rho_g * (10.0 - n.y));
    const auto forces = FacePressureLoads(mesh).compute(kBlocks, p, std::vector<double>{0.0, 0.0});
    for (std::size_t b = 0; b < kBlocks.size(); ++b) {
      Point f{};
      for (Point v : forces[b]) f += v;
      const double buoyancy = rho_g * geometry::area(kBlocks[b]);
      EXPECT_NEAR(f.y, buoyancy, 1e-12 * buoyancy) << cells << " cells, block " << b;
      EXPECT_NEAR(f.x, 0.0, 1e-12 * buoyancy) << cells << " cells, block " << b;
    }
  }
}

TEST(PressureForces, FaceIntegralsAreExactForTheP1Field) {
  // ∫ (1 − s/L) p ds and ∫ (s/L) p ds of the P1 field against a midpoint rule of 2e5 points
  // through pressure_at (its error, from the kinks at element edges, is below 1e-10 of the
  // integral): within 1e-9 relative, for a face across the elements, one along a line of
  // element edges (shared by two elements: counted once) and one along the mesh boundary.
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 80, 80);
  const std::vector<double> p = nodal_values(mesh, wavy_pressure);
  const FacePressureLoads loads(mesh);
  const std::vector<std::pair<Point, Point>> faces{
      {{0.13, 0.27}, {1.91, 1.62}}, {{0.3, 1.0}, {1.7, 1.0}}, {{2.0, 0.2}, {2.0, 1.9}}};
  for (const auto& [a, b] : faces) {
    const int n = 200000;
    const double length = geometry::distance(a, b);
    double start = 0.0, end = 0.0;
    for (int k = 0; k < n; ++k) {
      const double t = (k + 0.5) / n;
      const double value = loads.pressure_at(a + t * (b - a), p) * length / n;
      start += (1.0 - t) * value;
      end += t * value;
    }
    const auto exact = loads.integrate_along(a, b, p);
    EXPECT_FALSE(exact.leaves_mesh);
    EXPECT_NEAR(exact.start_inside, start, 1e-9 * start);
    EXPECT_NEAR(exact.end_inside, end, 1e-9 * end);
  }
}

TEST(PressureForces, APointInsideTakesThePressureOfTheElementThePointLocatorFinds) {
  // Inside the mesh pressure_at is the P1 field of the lowest-numbered element holding the
  // point, as mesh::PointLocator finds it, on edges and at nodes too: the same number exactly.
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 8, 8);
  const std::vector<double> p = nodal_values(mesh, wavy_pressure);
  const FacePressureLoads loads(mesh);
  const mesh::PointLocator locator(mesh);
  int checked = 0;
  for (int i = 0; i <= 32; ++i)
    for (int j = 0; j <= 32; ++j) {
      const Point q{2.0 * i / 32.0, 2.0 * j / 32.0};  // nodes, edge points and interiors
      const int t = locator.locate(q);
      ASSERT_GE(t, 0);
      EXPECT_EQ(loads.pressure_at(q, p), hydro::interpolate_pressure(mesh, p, t, q)) << q.x << ", " << q.y;
      ++checked;
    }
  EXPECT_EQ(checked, 33 * 33);
}

TEST(PressureForces, PointOutsideTheMeshTakesTheNearestMeshPoint) {
  // Outside the mesh the pressure is the P1 field's at the nearest point of the mesh boundary:
  // a point 0.1 m right of the side x = 2 takes the pressure at (2, y), exactly; a face
  // leaving the mesh integrates that rule over its part outside (linear between its ends),
  // which is then the face's outside part: within p × 1e-11 m, five times the distance within
  // which a point counts as on an element's edge (1e-12 of the mesh's 2 m).
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 8, 8);
  const std::vector<double> p = nodal_values(mesh, wavy_pressure);
  const FacePressureLoads loads(mesh);
  const int inside = mesh::PointLocator(mesh).locate({2.0 - 1e-9, 0.77});
  ASSERT_GE(inside, 0);
  EXPECT_NEAR(loads.pressure_at({2.1, 0.77}, p), hydro::interpolate_pressure(mesh, p, inside, {2.0, 0.77}),
              1e-12 * 1e7);
  const auto crossing = loads.integrate_along({1.5, 0.77}, {2.1, 0.77}, p);
  EXPECT_TRUE(crossing.leaves_mesh);
  const double p_boundary = loads.pressure_at({2.0, 0.77}, p);  // the outside part's pressure, at both its ends
  EXPECT_NEAR(crossing.start_outside + crossing.end_outside, 0.1 * p_boundary, 1e-11 * 1.4e7);
  // Its end load: ∫ (s/L) p over s in [0.5, 0.6] of L = 0.6.
  EXPECT_NEAR(crossing.end_outside, p_boundary * (0.6 * 0.6 - 0.5 * 0.5) / (2.0 * 0.6), 1e-11 * 1.4e7);
}

TEST(PressureForces, FaceJustOffTheBoundaryTakesTheBoundaryPressure) {
  // A block face along the mesh boundary but 1e-10 m outside it (a block that has slid by
  // that much) takes, point by point, the pressure of the boundary beside it: its integrals
  // are those of the face on the boundary, 1e-9 relative, though the pressure along it is far
  // from linear between its ends (the nearest mesh point runs along several boundary edges).
  const auto mesh = testing::make_rectangle_mesh(0.0, 0.0, 2.0, 2.0, 19, 23);
  const std::vector<double> p = nodal_values(mesh, wavy_pressure);
  const FacePressureLoads loads(mesh);
  const auto on = loads.integrate_along({0.0, 1.9}, {0.0, 0.1}, p);
  const auto off = loads.integrate_along({-1e-10, 1.9}, {-1e-10, 0.1}, p);
  EXPECT_FALSE(on.leaves_mesh);
  EXPECT_TRUE(off.leaves_mesh);
  EXPECT_NEAR(off.start_outside, on.start_inside, 1e-9 * on.start_inside);
  EXPECT_NEAR(off.end_outside, on.end_inside, 1e-9 * on.end_inside);
}

}  // namespace
}  // namespace hydrodda::coupling
