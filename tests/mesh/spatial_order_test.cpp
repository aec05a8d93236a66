// mesh::order_spatially and hilbert_index: the renumbering leaves the mesh the same set of
// triangles, nodes, regions and boundary edges (exact: only indices move), and puts neighbours
// in space near each other in memory.

#include "mesh/spatial_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace hydrodda::mesh {
namespace {

// The first 4^k cells of the curve are the 2^k × 2^k square at the origin, each visited once,
// and consecutive cells share a side (the curve's defining properties), here for k = 4.
TEST(SpatialOrder, TheHilbertCurveFillsEachSquareCellBySideSharingSteps) {
  constexpr std::uint32_t side = 16;
  std::vector<std::array<std::uint32_t, 2>> cell_at(side * side, {side, side});
  for (std::uint32_t x = 0; x < side; ++x)
    for (std::uint32_t y = 0; y < side; ++y) {
      const std::uint64_t d = hilbert_index(x, y);
      ASSERT_LT(d, side * side) << x << ", " << y;
      EXPECT_EQ(cell_at[d][0], side) << "cell " << d << " visited twice";
      cell_at[d] = {x, y};
    }
  for (std::size_t d = 1; d < cell_at.size(); ++d) {
    const long dx = std::labs(static_cast<long>(cell_at[d][0]) - static_cast<long>(cell_at[d - 1][0]));
    const long dy = std::labs(static_cast<long>(cell_at[d][1]) - static_cast<long>(cell_at[d - 1][1]));
    EXPECT_EQ(dx + dy, 1) << "step " << d;
  }
}

// An nx × ny grid of squares, two triangles each, numbered at random; region 1 the left half;
// the bottom edges a named boundary.
TriangleMesh shuffled_grid(int nx, int ny, unsigned seed) {
  TriangleMesh mesh;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.nodes.push_back({0.1 * i, 0.1 * j});
  const auto node = [&](int i, int j) { return j * (nx + 1) + i; };
  mesh.region_names = {"", "left"};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int region = 2 * i < nx ? 1 : 0;
      mesh.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      mesh.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
      mesh.region.push_back(region);
      mesh.region.push_back(region);
    }
  mesh.boundary_names = {"bottom"};
  for (int i = 0; i < nx; ++i) mesh.boundary_edges.push_back({{node(i, 0), node(i + 1, 0)}, 0});
  std::mt19937 random(seed);
  std::vector<int> order(mesh.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), random);
  TriangleMesh shuffled = mesh;
  for (std::size_t k = 0; k < order.size(); ++k) {
    shuffled.triangles[k] = mesh.triangles[order[k]];
    shuffled.region[k] = mesh.region[order[k]];
  }
  return shuffled;
}

using Corners = std::tuple<double, double, double, double, double, double, int>;
std::multiset<Corners> triangles_by_coordinates(const TriangleMesh& mesh) {
  std::multiset<Corners> out;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& c = mesh.triangles[t];
    out.insert({mesh.nodes[c[0]].x, mesh.nodes[c[0]].y, mesh.nodes[c[1]].x, mesh.nodes[c[1]].y, mesh.nodes[c[2]].x,
                mesh.nodes[c[2]].y, mesh.region[t]});
  }
  return out;
}

// Mean |s − t| over pairs of triangles that share a side, over the triangle count.
double mean_neighbour_distance(const TriangleMesh& mesh) {
  std::vector<std::vector<int>> of_node(mesh.nodes.size());
  for (int t = 0; t < mesh.triangle_count(); ++t)
    for (int v : mesh.triangles[t]) of_node[v].push_back(t);
  double sum = 0.0;
  long pairs = 0;
  for (int t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      for (int s : of_node[a])
        if (s > t && std::count(mesh.triangles[s].begin(), mesh.triangles[s].end(), b)) {
          sum += s - t;
          ++pairs;
        }
    }
  return sum / pairs / mesh.triangle_count();
}

TEST(SpatialOrder, RenumbersWithoutChangingTheMeshAndPutsNeighboursTogether) {
  const TriangleMesh before = shuffled_grid(60, 40, 3);
  TriangleMesh after = before;
  order_spatially(after);

  // The same triangles (corners in the same order, so still counter-clockwise), each with its
  // region; the same nodes; the same boundary edges, by coordinates.
  EXPECT_EQ(triangles_by_coordinates(after), triangles_by_coordinates(before));
  std::vector<Point> nodes_before = before.nodes, nodes_after = after.nodes;
  const auto by_xy = [](Point a, Point b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
  std::sort(nodes_before.begin(), nodes_before.end(), by_xy);
  std::sort(nodes_after.begin(), nodes_after.end(), by_xy);
  EXPECT_EQ(nodes_after, nodes_before);
  ASSERT_EQ(after.boundary_edges.size(), before.boundary_edges.size());
  for (std::size_t e = 0; e < before.boundary_edges.size(); ++e) {
    EXPECT_EQ(after.nodes[after.boundary_edges[e].nodes[0]], before.nodes[before.boundary_edges[e].nodes[0]]);
    EXPECT_EQ(after.nodes[after.boundary_edges[e].nodes[1]], before.nodes[before.boundary_edges[e].nodes[1]]);
    EXPECT_EQ(after.boundary_edges[e].boundary, before.boundary_edges[e].boundary);
  }

  // Numbered at random, neighbours lie a third of the mesh apart on average (0.333 here); along
  // the curve, under a per cent (0.0095: neighbours across the curve's quadrant borders).
  EXPECT_GT(mean_neighbour_distance(before), 0.25);
  EXPECT_LT(mean_neighbour_distance(after), 0.02);

  // The numbering depends on the mesh alone, not on the order it came in.
  TriangleMesh other = shuffled_grid(60, 40, 4);
  order_spatially(other);
  EXPECT_EQ(other.triangles, after.triangles);
  EXPECT_EQ(other.nodes, after.nodes);
}

}  // namespace
}  // namespace hydrodda::mesh
