#include "hydro/flow_failure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace hydrodda::hydro {

namespace {

// The principal values of a 2×2 symmetric tensor, smaller first.
std::array<double, 2> principal_values(const PermeabilityTensor& k) {
  const double mean = 0.5 * (k.xx + k.yy), half = 0.5 * (k.xx - k.yy);
  const double radius = std::sqrt(half * half + k.xy * k.xy);
  return {mean - radius, mean + radius};
}

std::string format_g(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string where(const mesh::TriangleMesh& mesh, int t) {
  const geometry::Point c = mesh::triangle_centroid(mesh, t);
  return "element " + std::to_string(t) + " at (" + format_g(c.x) + ", " + format_g(c.y) + ")";
}

std::string where_node(const mesh::TriangleMesh& mesh, int v) {
  return "node " + std::to_string(v) + " (" + format_g(mesh.nodes[v].x) + ", " + format_g(mesh.nodes[v].y) + ")";
}

// The first node of a part of the mesh that reaches no fixed-head node through elements whose
// smaller principal permeability is at least `floor` (0: through any element); −1 when every
// part does. A union–find over the nodes of those elements, as DarcySolver's own check.
int find_part_cut_off(const mesh::TriangleMesh& mesh, PermeabilityView permeability,
                      std::span<const double> fixed_head, double floor) {
  std::vector<int> parent(mesh.nodes.size());
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  const auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    if (principal_values(permeability[t])[0] < floor) continue;
    const auto& tri = mesh.triangles[t];
    for (int k = 1; k < 3; ++k) {
      const int a = find(tri[0]), b = find(tri[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<char> fixed_part(mesh.nodes.size(), 0);
  for (std::size_t v = 0; v < fixed_head.size(); ++v)
    if (!std::isnan(fixed_head[v])) fixed_part[find(static_cast<int>(v))] = 1;
  for (const auto& tri : mesh.triangles)
    for (int v : tri)
      if (!fixed_part[find(v)]) return v;
  return -1;
}

}  // namespace

std::string describe_flow_failure(const mesh::TriangleMesh& mesh, PermeabilityView permeability,
                                  std::span<const double> fixed_head, const std::string& what_failed) {
  std::string text = "the flow solve failed (" + what_failed + ")";
  if (permeability.size() != mesh.triangles.size() || permeability.size() == 0) return text;
  int smallest = 0, largest = 0;
  double k_min = INFINITY, k_max = -INFINITY;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const std::array<double, 2> k = principal_values(permeability[t]);
    if (k[0] < k_min) k_min = k[0], smallest = t;
    if (k[1] > k_max) k_max = k[1], largest = t;
  }
  text += ": the permeability spans " + format_g(k_min) + " m² (" + where(mesh, smallest) + ") to " +
          format_g(k_max) + " m² (" + where(mesh, largest) + ")";
  if (k_min > 0.0) text += ", a contrast of " + format_g(k_max / k_min);
  // Disconnected (a part of the mesh with no fixed head at all, whatever the permeability)
  // and ill-conditioned (a part that reaches a fixed head only through elements round-off
  // loses) are different faults with different cures: each is named only where it is true.
  const int floating = find_part_cut_off(mesh, permeability, fixed_head, 0.0);
  if (floating >= 0)
    return text + "; the part of the mesh around " + where_node(mesh, floating) +
           " touches no fixed-head boundary: its head is undetermined";
  if (k_min < kLostToRoundOff * k_max) text += ", past the 1e16 that double precision resolves";
  const int cut_off = find_part_cut_off(mesh, permeability, fixed_head, kLostToRoundOff * k_max);
  if (cut_off >= 0)
    text += "; the system is ill-conditioned, not disconnected: the part of the mesh around " +
            where_node(mesh, cut_off) +
            " reaches a fixed-head boundary only through elements whose permeability is under 1e-16 of the largest, "
            "whose flow round-off loses beside it (a lower cap on the largest permeability keeps the contrast "
            "inside what the solve resolves)";
  return text;
}

}  // namespace hydrodda::hydro
