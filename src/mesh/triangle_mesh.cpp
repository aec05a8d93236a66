#include "mesh/triangle_mesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace hydrodda::mesh {

double triangle_area(const TriangleMesh& mesh, int t) {
  const auto& [a, b, c] = mesh.triangles[t];
  return 0.5 * geometry::orient(mesh.nodes[a], mesh.nodes[b], mesh.nodes[c]);
}

Point triangle_centroid(const TriangleMesh& mesh, int t) {
  const auto& [a, b, c] = mesh.triangles[t];
  return (mesh.nodes[a] + mesh.nodes[b] + mesh.nodes[c]) / 3.0;
}

namespace {
int find_name(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}
}  // namespace

int find_boundary(const TriangleMesh& mesh, const std::string& name) {
  return find_name(mesh.boundary_names, name);
}

int find_region(const TriangleMesh& mesh, const std::string& name) {
  return find_name(mesh.region_names, name);
}

std::vector<int> select_region(const TriangleMesh& mesh, const std::string& name) {
  const int tag = find_region(mesh, name);
  if (tag < 0) throw std::runtime_error("mesh has no region named '" + name + "'");
  std::vector<int> selected;
  for (int t = 0; t < mesh.triangle_count(); ++t)
    if (mesh.region[t] == tag) selected.push_back(t);
  return selected;
}

// An edge of the boundary belongs to one triangle; an inner edge to two. The edges are
// bucketed by their lower node (a counting sort: linear, where sorting all 3 T edges took a
// third of a second at a million triangles), each bucket ordered by the higher node, and the
// edges that occur once kept: the boundary in the order of their (lower, higher) node pairs.
std::vector<BoundarySide> find_boundary_sides(const std::vector<std::array<int, 3>>& triangles) {
  struct Edge {
    int hi, from, to, triangle;
  };
  int node_count = 0;
  for (const auto& tri : triangles) node_count = std::max({node_count, tri[0] + 1, tri[1] + 1, tri[2] + 1});
  std::vector<int> start(static_cast<std::size_t>(node_count) + 1, 0);
  for (const auto& tri : triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(tri[k], tri[(k + 1) % 3]) + 1];
  for (int v = 0; v < node_count; ++v) start[v + 1] += start[v];
  std::vector<Edge> edges(3 * triangles.size());
  std::vector<int> next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      edges[next[std::min(a, b)]++] = {std::max(a, b), a, b, static_cast<int>(t)};
    }
  std::vector<BoundarySide> boundary;
  for (int lo = 0; lo < node_count; ++lo) {
    // A node's bucket holds a handful of edges: insertion sort.
    const auto first = edges.begin() + start[lo], last = edges.begin() + start[lo + 1];
    for (auto i = first; i != last; ++i)
      for (auto j = i; j != first && (j - 1)->hi > j->hi; --j) std::iter_swap(j - 1, j);
    for (auto i = first; i != last;) {
      auto j = i + 1;
      while (j != last && j->hi == i->hi) ++j;
      if (j - i == 1) boundary.push_back({{i->from, i->to}, i->triangle});
      i = j;
    }
  }
  return boundary;
}

std::vector<std::array<int, 2>> find_boundary_edges(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<std::array<int, 2>> edges;
  for (const BoundarySide& side : find_boundary_sides(triangles)) edges.push_back(side.edge);
  return edges;
}

void validate(const TriangleMesh& mesh) {
  const int n = mesh.node_count();
  if (mesh.region.size() != mesh.triangles.size())
    throw std::runtime_error("mesh: " + std::to_string(mesh.region.size()) + " region tags for " +
                             std::to_string(mesh.triangles.size()) + " triangles");
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    for (int v : mesh.triangles[t])
      if (v < 0 || v >= n)
        throw std::runtime_error("mesh: triangle " + std::to_string(t) + " has node " +
                                 std::to_string(v) + " out of range");
    if (!(triangle_area(mesh, t) > 0.0))
      throw std::runtime_error("mesh: triangle " + std::to_string(t) +
                               " is clockwise or degenerate");
    if (mesh.region[t] < 0 || mesh.region[t] >= static_cast<int>(mesh.region_names.size()))
      throw std::runtime_error("mesh: triangle " + std::to_string(t) + " has region tag " +
                               std::to_string(mesh.region[t]) + " out of range");
  }
  for (const BoundaryEdge& e : mesh.boundary_edges) {
    for (int v : e.nodes)
      if (v < 0 || v >= n) throw std::runtime_error("mesh: boundary edge node out of range");
    if (e.boundary < BoundaryEdge::kUnnamed ||
        e.boundary >= static_cast<int>(mesh.boundary_names.size()))
      throw std::runtime_error("mesh: boundary edge tag out of range");
  }
}

}  // namespace hydrodda::mesh
