#include "mesh/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace hydrodda::mesh {

namespace {
constexpr int kOrder = 16;
constexpr std::uint32_t kSide = 1u << kOrder;
}  // namespace

// Pseudocode (the Hilbert curve's index of a cell, Hamilton's iterative form; Butz, IEEE Trans.
// Computers C-20, 1971), for quadrant size s = 2^15 … 1:
//   rx = (x & s) > 0; ry = (y & s) > 0
//   d += s² · ((3 · rx) ^ ry)
//   turn the quadrant: if ry = 0 { if rx = 1 { x = s − 1 − x; y = s − 1 − y }; swap x, y }
// Written by hand: a dozen lines that no library of the project's provides.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = kSide / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - (x & (s - 1));
        y = s - 1 - (y & (s - 1));
      }
      std::swap(x, y);
    }
    x &= s - 1;
    y &= s - 1;
  }
  return d;
}

void order_spatially(TriangleMesh& mesh) {
  const std::size_t triangles = mesh.triangles.size(), nodes = mesh.nodes.size();
  if (triangles == 0) return;
  Point lo = mesh.nodes[mesh.triangles[0][0]], hi = lo;
  for (const auto& t : mesh.triangles)
    for (int v : t) {
      lo = {std::min(lo.x, mesh.nodes[v].x), std::min(lo.y, mesh.nodes[v].y)};
      hi = {std::max(hi.x, mesh.nodes[v].x), std::max(hi.y, mesh.nodes[v].y)};
    }
  const double side = std::max({hi.x - lo.x, hi.y - lo.y, 1e-300});
  const auto cell = [&](double v, double origin) {
    const double scaled = std::floor((v - origin) / side * kSide);
    return static_cast<std::uint32_t>(std::clamp(scaled, 0.0, static_cast<double>(kSide - 1)));
  };
  std::vector<std::uint64_t> key(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const Point c = triangle_centroid(mesh, static_cast<int>(t));
    key[t] = hilbert_index(cell(c.x, lo.x), cell(c.y, lo.y));
  }
  std::vector<int> order(triangles);  // order[new] = old
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });

  std::vector<int> new_node(nodes, -1);
  int next = 0;
  for (int t : order)
    for (int v : mesh.triangles[t])
      if (new_node[v] < 0) new_node[v] = next++;
  for (std::size_t v = 0; v < nodes; ++v)
    if (new_node[v] < 0) new_node[v] = next++;

  std::vector<std::array<int, 3>> new_triangles(triangles);
  for (std::size_t k = 0; k < triangles; ++k)
    for (int c = 0; c < 3; ++c) new_triangles[k][c] = new_node[mesh.triangles[order[k]][c]];
  mesh.triangles = std::move(new_triangles);
  if (mesh.region.size() == triangles) {
    std::vector<int> region(triangles);
    for (std::size_t k = 0; k < triangles; ++k) region[k] = mesh.region[order[k]];
    mesh.region = std::move(region);
  }
  std::vector<Point> new_nodes(nodes);
  for (std::size_t v = 0; v < nodes; ++v) new_nodes[new_node[v]] = mesh.nodes[v];
  mesh.nodes = std::move(new_nodes);
  for (BoundaryEdge& e : mesh.boundary_edges)
    for (int& v : e.nodes) v = new_node[v];
}

}  // namespace hydrodda::mesh
