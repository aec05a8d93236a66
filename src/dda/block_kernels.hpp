#pragma once
// Per-block kernels of first-order DDA (Shi 1988, ch. 2): the displacement function T, the
// 6×6 element matrices and load vectors, and the exact-rotation point update. Pure functions
// of plain data. Unknowns D = (u0, v0, r0, εx, εy, γxy) about the block centroid (x0, y0):
//   u = u0 − (y−y0) r0 + (x−x0) εx + (y−y0) γxy/2
//   v = v0 + (x−x0) r0 + (y−y0) εy + (x−x0) γxy/2

#include <cmath>
#include <span>

#include <Eigen/Dense>

#include "dda/definitions.hpp"

namespace hydrodda::dda {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix26 = Eigen::Matrix<double, 2, 6>;
using Vector3 = Eigen::Vector3d;

// Area, centroid and central second moments ∫X², ∫Y², ∫XY (X = x − x0, Y = y − y0).
struct Moments {
  double area = 0.0;
  Point centroid;
  double sxx = 0.0;
  double syy = 0.0;
  double sxy = 0.0;
};
Moments compute_moments(std::span<const Point> polygon);

// T(x, y): the point's displacement is T·D.
Matrix26 compute_displacement_matrix(Point p, Point centroid);
// T·D written out, for loops over every vertex that need no matrix: with (x, y) from the
// centroid, (u0 − r0 y + εx x + γ y/2, v0 + r0 x + εy y + γ x/2).
inline Point first_order_displacement(Point p, Point centroid, const Vector6& d) {
  const double x = p.x - centroid.x;
  const double y = p.y - centroid.y;
  return {d[0] - d[2] * y + d[3] * x + d[5] * y / 2, d[1] + d[2] * x + d[4] * y + d[5] * x / 2};
}

// 3×3 elasticity matrix: σ = E ε with ε = (εx, εy, γxy).
Eigen::Matrix3d compute_elasticity(const Material& material, Plane plane);

// Elastic strain energy ½ A εᵀ E ε: stiffness A·E on the strain unknowns (rows 3..5).
Matrix6 compute_elastic_stiffness(const Moments& m, const Eigen::Matrix3d& elasticity);

// M = ρ ∫ Tᵀ T dA.
Matrix6 compute_mass_matrix(const Moments& m, double density);

// Load of a traction varying linearly from t_a at a to t_b at b along segment ab:
// F = ∫ Tᵀ t ds, exact by Simpson's rule since the integrand is quadratic in s.
Vector6 compute_segment_load(Point a, Point b, Point t_a, Point t_b, Point centroid);

// Traction on the edge a→b of a counter-clockwise polygon, normal positive outward.
Vector6 compute_edge_traction_load(Point a, Point b, Point centroid, double normal_a,
                                   double normal_b, double shear_a, double shear_b);

// The points of a block after its displacement D about `centroid`, the rotation applied
// exactly (cos r0, sin r0) so that a rigid rotation keeps lengths and areas; strain terms as
// in T. The cosine and sine are computed once for all the block's points.
class BlockMotion {
 public:
  BlockMotion(Point centroid, const Vector6& d)
      : centroid_(centroid), d_(d), cos_minus_one_(std::cos(d[2]) - 1), sin_(std::sin(d[2])) {}
  Point operator()(Point p) const {
    const double x = p.x - centroid_.x;
    const double y = p.y - centroid_.y;
    return {p.x + d_[0] + cos_minus_one_ * x - sin_ * y + x * d_[3] + y * d_[5] / 2,
            p.y + d_[1] + sin_ * x + cos_minus_one_ * y + y * d_[4] + x * d_[5] / 2};
  }

 private:
  Point centroid_;
  Vector6 d_;
  double cos_minus_one_, sin_;
};

// One point after the block displacement D (BlockMotion).
inline Point displace_point(Point p, Point centroid, const Vector6& d) { return BlockMotion(centroid, d)(p); }

}  // namespace hydrodda::dda
