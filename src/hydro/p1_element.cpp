#include "hydro/p1_element.hpp"

namespace hydrodda::hydro {

using geometry::Point;

std::array<Point, 3> compute_shape_gradients(Point a, Point b, Point c) {
  const double twice_area = geometry::orient(a, b, c);
  const double s = 1.0 / twice_area;
  return {Point{(b.y - c.y) * s, (c.x - b.x) * s},   // ∇φ_a
          Point{(c.y - a.y) * s, (a.x - c.x) * s},   // ∇φ_b
          Point{(a.y - b.y) * s, (b.x - a.x) * s}};  // ∇φ_c
}

std::array<std::array<double, 3>, 3> compute_element_matrix(Point a, Point b, Point c,
                                                            const Conductivity& k) {
  const double area = 0.5 * geometry::orient(a, b, c);
  const auto g = compute_shape_gradients(a, b, c);
  std::array<std::array<double, 3>, 3> m{};
  for (int j = 0; j < 3; ++j) {
    // K ∇φ_j
    const Point kg{k.xx * g[j].x + k.xy * g[j].y, k.xy * g[j].x + k.yy * g[j].y};
    for (int i = 0; i < j; ++i) m[i][j] = m[j][i] = area * geometry::dot(kg, g[i]);
  }
  // Σ_j ∇φ_j = 0, so each row sums to zero: take the diagonal from the off-diagonal terms,
  // which keeps A·1 = 0 to the last bit per element (the mass balance rests on it).
  for (int i = 0; i < 3; ++i) m[i][i] = -(m[i][(i + 1) % 3] + m[i][(i + 2) % 3]);
  return m;
}

}  // namespace hydrodda::hydro
