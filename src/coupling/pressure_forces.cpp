#include "coupling/pressure_forces.hpp"

#include <limits>
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
  centroids_.reserve(mesh.triangles.size());
  for (int t = 0; t < mesh.triangle_count(); ++t) centroids_.push_back(mesh::triangle_centroid(mesh, t));
}

int VertexPressureSampler::find_nearest_element(Point p) const {
  // Rare (only vertices outside the fluid domain): a plain scan is enough.
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < centroids_.size(); ++t) {
    const double d = geometry::distance(p, centroids_[t]);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(t);
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
      if (t < 0) t = find_nearest_element(v);
      out[b].push_back(element_pressure[t]);
    }
  }
  return out;
}

}  // namespace hydrodda::coupling
