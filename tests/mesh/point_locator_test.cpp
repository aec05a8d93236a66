// Point location against a brute-force search.
#include <gtest/gtest.h>

#include <random>

#include "mesh/mesh_request.hpp"
#include "mesh/point_locator.hpp"

namespace hydrodda::mesh {
namespace {

bool contains(const TriangleMesh& m, int t, Point p) {
  const auto& [a, b, c] = m.triangles[t];
  const double tol = -1e-12;
  return geometry::orient(m.nodes[a], m.nodes[b], p) >= tol &&
         geometry::orient(m.nodes[b], m.nodes[c], p) >= tol &&
         geometry::orient(m.nodes[c], m.nodes[a], p) >= tol;
}

// Random points in and around a refined L-shaped mesh: a located triangle contains the
// point; a point reported outside is contained by no triangle.
TEST(PointLocator, AgreesWithBruteForce) {
  MeshRequest r;
  r.domain = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  r.size = 0.1;
  r.refinement_lines = {{{0.1, 0.1}, {1.9, 0.9}}};
  r.fracture_size = 0.01;
  const TriangleMesh m = generate_mesh(r);
  const PointLocator locator(m);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 2.2);
  int inside = 0;
  for (int i = 0; i < 3000; ++i) {
    const Point p{u(rng), u(rng)};
    const int t = locator.locate(p);
    if (t >= 0) {
      ASSERT_TRUE(contains(m, t, p));
      ++inside;
    } else {
      for (int s = 0; s < m.triangle_count(); ++s) ASSERT_FALSE(contains(m, s, p)) << p.x << " " << p.y;
    }
  }
  EXPECT_GT(inside, 1000);
  // Every node and centroid is found.
  for (int t = 0; t < m.triangle_count(); ++t) ASSERT_EQ(locator.locate(triangle_centroid(m, t)), t);
  for (const Point& p : m.nodes) ASSERT_GE(locator.locate(p), 0);
}

}  // namespace
}  // namespace hydrodda::mesh
