#include "hydro/region_flow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "hydro/p1_element.hpp"

namespace hydrodda::hydro {

using geometry::Point;

RegionFlow compute_region_flow(const mesh::TriangleMesh& mesh, const FlowSolution& solution,
                               std::span<const int> triangles, std::optional<Point> direction) {
  if (triangles.empty()) throw std::runtime_error("region flow: the region has no triangles");
  RegionFlow out;
  Point flux_integral{}, gradient_integral{};
  for (int t : triangles) {
    const auto& tri = mesh.triangles[t];
    const double a = mesh::triangle_area(mesh, t);
    const auto g = compute_shape_gradients(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]);
    const Point grad = solution.head[tri[0]] * g[0] + solution.head[tri[1]] * g[1] +
                       solution.head[tri[2]] * g[2];
    out.area += a;
    flux_integral += a * solution.flux[t];
    gradient_integral += a * grad;
  }
  Point d = direction.value_or(flux_integral);
  if (!(geometry::norm(d) > 0.0)) d = {1.0, 0.0};
  d = d / geometry::norm(d);
  const Point across{-d.y, d.x};
  double lo = INFINITY, hi = -INFINITY, lo_across = INFINITY, hi_across = -INFINITY;
  for (int t : triangles)
    for (int v : mesh.triangles[t]) {
      const double s = geometry::dot(mesh.nodes[v], d), c = geometry::dot(mesh.nodes[v], across);
      lo = std::min(lo, s), hi = std::max(hi, s);
      lo_across = std::min(lo_across, c), hi_across = std::max(hi_across, c);
    }
  out.direction = d;
  out.mean_head_gradient = -1.0 * gradient_integral / out.area;
  out.length = hi - lo;
  out.width = hi_across - lo_across;
  out.flow = geometry::dot(flux_integral, d) / out.length;
  out.head_gradient = -geometry::dot(gradient_integral, d) / out.area;
  out.effective_conductivity = out.head_gradient != 0.0
                                   ? out.flow / (out.width * out.head_gradient)
                                   : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace hydrodda::hydro
