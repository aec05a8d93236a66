// The mesh boundary's sides against a count of every edge's triangles.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "mesh/mesh_request.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::mesh {
namespace {

// An edge is on the boundary exactly when one triangle has it. On an L-shaped mesh with a
// hole, refined along a line: the sides found are those edges, each oriented as in its
// triangle and with that triangle, in the order of their (lower, higher) node pairs.
TEST(BoundarySides, AreTheEdgesOfOneTriangleInNodeOrder) {
  MeshRequest r;
  r.domain = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  r.size = 0.1;
  r.refinement_lines = {{{0.1, 0.1}, {1.9, 0.9}}};
  r.fracture_size = 0.02;
  TriangleMesh m = generate_mesh(r);
  // A hole: drop the triangles whose centroid lies in a square.
  std::vector<std::array<int, 3>> kept;
  for (int t = 0; t < m.triangle_count(); ++t) {
    const Point c = triangle_centroid(m, t);
    if (!(c.x > 0.3 && c.x < 0.6 && c.y > 1.2 && c.y < 1.5)) kept.push_back(m.triangles[t]);
  }
  ASSERT_LT(kept.size(), m.triangles.size());

  std::map<std::pair<int, int>, std::vector<std::pair<std::array<int, 2>, int>>> by_edge;
  for (std::size_t t = 0; t < kept.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = kept[t][k], b = kept[t][(k + 1) % 3];
      by_edge[{std::min(a, b), std::max(a, b)}].push_back({{a, b}, static_cast<int>(t)});
    }
  std::vector<BoundarySide> expected;  // the map iterates in (lower, higher) order
  for (const auto& [pair, uses] : by_edge) {
    ASSERT_LE(uses.size(), 2u);
    if (uses.size() == 1) expected.push_back({uses[0].first, uses[0].second});
  }

  const std::vector<BoundarySide> found = find_boundary_sides(kept);
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(found[i].edge, expected[i].edge) << i;
    EXPECT_EQ(found[i].triangle, expected[i].triangle) << i;
  }
  // The outer boundary and the hole's: more sides than the outer polygon's alone.
  EXPECT_GT(found.size(), 8.0 / 0.1);
}

TEST(BoundarySides, OfNoTrianglesAreNone) { EXPECT_TRUE(find_boundary_sides({}).empty()); }

}  // namespace
}  // namespace hydrodda::mesh
