#include "coupling/pressure_forces.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

namespace hydrodda::coupling {

std::vector<std::vector<Point>> compute_edge_load_forces(std::span<const geometry::Polygon> blocks,
                                                         std::span<const std::vector<double>> vertex_pressure) {
  if (vertex_pressure.size() != blocks.size())
    throw std::invalid_argument("pressure forces: one pressure list per block is needed");
  std::vector<std::vector<Point>> forces(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const geometry::Polygon& poly = blocks[b];
    const std::vector<double>& p = vertex_pressure[b];
    if (p.size() != poly.size())
      throw std::invalid_argument("pressure forces: one pressure per block vertex is needed");
    const std::size_t n = poly.size();
    forces[b].assign(n, Point{});
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const Point edge = poly[j] - poly[i];
      // L × inward normal of a counter-clockwise polygon: the edge turned left, (−dy, dx).
      const Point l_inward{-edge.y, edge.x};
      forces[b][i] += ((2.0 * p[i] + p[j]) / 6.0) * l_inward;
      forces[b][j] += ((p[i] + 2.0 * p[j]) / 6.0) * l_inward;
    }
  }
  return forces;
}

VertexPressureSampler::VertexPressureSampler(const mesh::TriangleMesh& mesh) : mesh_(mesh), locator_(mesh) {
  // Boundary edges (in one triangle only), each with its triangle: built once per mesh.
  std::map<std::pair<int, int>, int> owner;  // sorted edge → triangle, or -1 when shared
  for (int t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto edge = std::minmax(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]);
      const auto [it, inserted] = owner.emplace(edge, t);
      if (!inserted) it->second = -1;
    }
  for (const auto& [edge, t] : owner)
    if (t >= 0) boundary_.push_back({mesh.nodes[edge.first], mesh.nodes[edge.second], t});
}

int VertexPressureSampler::find_nearest_boundary_element(Point p) const {
  // Rare (only vertices outside the fluid mesh): a scan of the boundary edges is enough.
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (const BoundarySide& side : boundary_) {
    const double d = geometry::distance_to_segment(p, side.a, side.b);
    if (d < best_d) {
      best_d = d;
      best = side.triangle;
    }
  }
  return best;
}

std::vector<std::vector<double>> VertexPressureSampler::sample(std::span<const geometry::Polygon> blocks,
                                                               std::span<const double> element_pressure) const {
  if (element_pressure.size() != mesh_.triangles.size())
    throw std::invalid_argument("pressure forces: one pressure per fluid element is needed");
  std::vector<std::vector<double>> out(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    out[b].reserve(blocks[b].size());
    for (Point v : blocks[b]) {
      int t = locator_.locate(v);
      if (t < 0) t = find_nearest_boundary_element(v);
      out[b].push_back(element_pressure[t]);
    }
  }
  return out;
}

}  // namespace hydrodda::coupling
