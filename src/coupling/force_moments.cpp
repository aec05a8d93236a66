#include "coupling/force_moments.hpp"

#include <cmath>
#include <stdexcept>

namespace hydrodda::coupling {

void ForceMoments::add(Point at, Point force) {
  const Point r = at - origin;
  resultant += force;
  xx += r.x * force.x;
  xy += r.x * force.y;
  yx += r.y * force.x;
  yy += r.y * force.y;
}

void ForceMoments::add_along(Point a, Point b, double q_a, double q_b, Point n) {
  // With x = a + t (b − a), t in [0, 1]: ∫ q ds = L (q_a + q_b)/2 and
  // ∫ (x − origin) q ds = L ((a − origin)(q_a + q_b)/2 + (b − a)(q_a + 2 q_b)/6).
  const double length = geometry::distance(a, b);
  const double total = length * 0.5 * (q_a + q_b);
  const Point weighted = length * ((0.5 * (q_a + q_b)) * (a - origin) + ((q_a + 2.0 * q_b) / 6.0) * (b - a));
  resultant += total * n;
  xx += weighted.x * n.x;
  xy += weighted.x * n.y;
  yx += weighted.y * n.x;
  yy += weighted.y * n.y;
}

Point vertex_mean(const geometry::Polygon& polygon) {
  Point m{};
  for (Point p : polygon) m += p;
  return m / static_cast<double>(polygon.size());
}

std::vector<Point> distribute_to_vertices(const geometry::Polygon& polygon, const ForceMoments& moments) {
  const std::size_t n = polygon.size();
  if (n < 3) throw std::invalid_argument("force moments: a block needs three vertices");
  const Point m = vertex_mean(polygon);
  // S = Σ X Xᵀ about the mean (so that Σ X = 0 and the resultant spreads evenly).
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (Point p : polygon) {
    const Point r = p - m;
    sxx += r.x * r.x;
    sxy += r.x * r.y;
    syy += r.y * r.y;
  }
  const double det = sxx * syy - sxy * sxy;
  if (!(det > 1e-12 * (sxx + syy) * (sxx + syy)))
    throw std::invalid_argument("force moments: a block's vertices lie on one line");
  // Moments about the mean from those about the origin: Σ (x − m) F = Σ (x − o) F − (m − o) R.
  const Point shift = m - moments.origin;
  const Point r = moments.resultant;
  const double xx = moments.xx - shift.x * r.x, xy = moments.xy - shift.x * r.y;
  const double yx = moments.yx - shift.y * r.x, yy = moments.yy - shift.y * r.y;
  // F_v,j = R_j / n + λ_j · X_v with S λ_j = (Σ X F_j, Σ Y F_j), for j = x, y.
  const auto solve = [&](double mx, double my) {
    return Point{(syy * mx - sxy * my) / det, (sxx * my - sxy * mx) / det};
  };
  const Point lambda_x = solve(xx, yx);
  const Point lambda_y = solve(xy, yy);
  std::vector<Point> forces(n);
  for (std::size_t v = 0; v < n; ++v) {
    const Point x = polygon[v] - m;
    forces[v] = r / static_cast<double>(n) + Point{dot(lambda_x, x), dot(lambda_y, x)};
  }
  return forces;
}

}  // namespace hydrodda::coupling
