#include "hydro/element_pressure.hpp"

#include "numerics/parallel.hpp"
#include "hydro/p1_element.hpp"

namespace hydrodda::hydro {

using geometry::Point;

std::vector<double> compute_centroid_pressure(const mesh::TriangleMesh& mesh,
                                              const FlowSolution& solution) {
  std::vector<double> p(mesh.triangles.size());
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const auto& [a, b, c] = mesh.triangles[t];
    p[t] = (solution.pressure[a] + solution.pressure[b] + solution.pressure[c]) / 3.0;
  }
  return p;
}

std::vector<Point> compute_pressure_gradients(const mesh::TriangleMesh& mesh, std::span<const double> nodal_pressure) {
  std::vector<Point> gradients(mesh.triangles.size());
  // Each element's own: the same values on any number of threads.
  numerics::for_each_index(mesh.triangles.size() >= 20000, mesh.triangles.size(), [&](std::size_t t) {
    const auto& nodes = mesh.triangles[t];
    const auto g = compute_shape_gradients(mesh.nodes[nodes[0]], mesh.nodes[nodes[1]], mesh.nodes[nodes[2]]);
    for (int i = 0; i < 3; ++i) gradients[t] += nodal_pressure[nodes[i]] * g[i];
  });
  return gradients;
}

double interpolate_pressure(const mesh::TriangleMesh& mesh, std::span<const double> nodal_pressure, int t, Point p) {
  const auto& nodes = mesh.triangles[t];
  const Point a = mesh.nodes[nodes[0]], b = mesh.nodes[nodes[1]], c = mesh.nodes[nodes[2]];
  // Barycentric weights: φ_a(p) = orient(p, b, c) / orient(a, b, c), and so on.
  const double whole = geometry::orient(a, b, c);
  const double wa = geometry::orient(p, b, c) / whole;
  const double wb = geometry::orient(a, p, c) / whole;
  const double wc = 1.0 - wa - wb;
  return wa * nodal_pressure[nodes[0]] + wb * nodal_pressure[nodes[1]] + wc * nodal_pressure[nodes[2]];
}

}  // namespace hydrodda::hydro
