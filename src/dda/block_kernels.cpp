#include "dda/block_kernels.hpp"

#include <array>
#include <cmath>

namespace hydrodda::dda {

Moments compute_moments(std::span<const Point> polygon) {
  Moments m;
  m.area = geometry::signed_area(polygon);
  m.centroid = geometry::centroid(polygon);
  // Second moments of a polygon about its centroid (Green's theorem on centred coordinates):
  // ∫x² = 1/12 Σ w (xi² + xi xj + xj²), ∫xy = 1/24 Σ w (2xi yi + xi yj + xj yi + 2xj yj),
  // w = xi yj − xj yi.
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = polygon[i] - m.centroid;
    const Point b = polygon[(i + 1) % n] - m.centroid;
    const double w = cross(a, b);
    m.sxx += w * (a.x * a.x + a.x * b.x + b.x * b.x);
    m.syy += w * (a.y * a.y + a.y * b.y + b.y * b.y);
    m.sxy += w * (2 * a.x * a.y + a.x * b.y + b.x * a.y + 2 * b.x * b.y);
  }
  m.sxx /= 12.0;
  m.syy /= 12.0;
  m.sxy /= 24.0;
  return m;
}

Matrix26 compute_displacement_matrix(Point p, Point centroid) {
  const double x = p.x - centroid.x;
  const double y = p.y - centroid.y;
  Matrix26 t;
  t << 1, 0, -y, x, 0, y / 2,  //
      0, 1, x, 0, y, x / 2;
  return t;
}

Eigen::Matrix3d compute_elasticity(const Material& material, Plane plane) {
  const double e = material.young;
  const double nu = material.poisson;
  Eigen::Matrix3d c;
  if (plane == Plane::stress) {
    const double k = e / (1 - nu * nu);
    c << k, k * nu, 0, k * nu, k, 0, 0, 0, k * (1 - nu) / 2;
  } else {
    const double k = e / ((1 + nu) * (1 - 2 * nu));
    c << k * (1 - nu), k * nu, 0, k * nu, k * (1 - nu), 0, 0, 0, k * (1 - 2 * nu) / 2;
  }
  return c;
}

Matrix6 compute_elastic_stiffness(const Moments& m, const Eigen::Matrix3d& elasticity) {
  Matrix6 k = Matrix6::Zero();
  k.block<3, 3>(3, 3) = m.area * elasticity;
  return k;
}

Matrix6 compute_mass_matrix(const Moments& m, double density) {
  // M = ρ ∫ Tᵀ T dA about the centroid (∫X = ∫Y = 0), with T's columns
  //   u0: (1, 0)   v0: (0, 1)   r0: (−Y, X)   εx: (X, 0)   εy: (0, Y)   γxy: (Y/2, X/2),
  // so that each entry is ∫ of the products of two columns: A for the translations,
  // Sxx = ∫X², Syy = ∫Y², Sxy = ∫XY for the rest (Shi 1988), written out: every step
  // assembles it for every block.
  const double a = m.area, sxx = m.sxx, syy = m.syy, sxy = m.sxy;
  Matrix6 mass = Matrix6::Zero();
  mass(0, 0) = mass(1, 1) = density * a;
  mass(2, 2) = density * (syy + sxx);                          // ∫(Y² + X²)
  mass(2, 3) = mass(3, 2) = density * -sxy;                    // ∫(−Y)(X)
  mass(2, 4) = mass(4, 2) = density * sxy;                     // ∫(X)(Y)
  mass(2, 5) = mass(5, 2) = density * (-0.5 * syy + 0.5 * sxx);  // ∫(−Y)(Y/2) + (X)(X/2)
  mass(3, 3) = density * sxx;
  mass(3, 5) = mass(5, 3) = density * (0.5 * sxy);             // ∫(X)(Y/2)
  mass(4, 4) = density * syy;
  mass(4, 5) = mass(5, 4) = density * (0.5 * sxy);             // ∫(Y)(X/2)
  mass(5, 5) = density * (0.25 * syy + 0.25 * sxx);            // ∫(Y/2)² + (X/2)²
  return mass;
}

Vector6 compute_segment_load(Point a, Point b, Point t_a, Point t_b, Point centroid) {
  const double length = geometry::distance(a, b);
  const Point mid = 0.5 * (a + b);
  const Point t_mid = 0.5 * (t_a + t_b);
  const auto term = [&](Point p, Point t) -> Vector6 {
    return compute_displacement_matrix(p, centroid).transpose() * Eigen::Vector2d(t.x, t.y);
  };
  return length / 6.0 * (term(a, t_a) + 4.0 * term(mid, t_mid) + term(b, t_b));
}

Vector6 compute_edge_traction_load(Point a, Point b, Point centroid, double normal_a,
                                   double normal_b, double shear_a, double shear_b) {
  const double length = geometry::distance(a, b);
  const Point s = (b - a) / length;
  const Point n{s.y, -s.x};  // outward for a counter-clockwise polygon
  return compute_segment_load(a, b, normal_a * n + shear_a * s, normal_b * n + shear_b * s,
                              centroid);
}

}  // namespace hydrodda::dda
