#pragma once
// The linear (P1) triangle: shape-function gradients and the element conductance matrix.

#include <array>

#include "geometry/point.hpp"

namespace hydrodda::hydro {

// A symmetric conductivity tensor (m/s): [[xx, xy], [xy, yy]].
struct Conductivity {
  double xx = 0.0;
  double xy = 0.0;
  double yy = 0.0;
};

// ∇φ_i of the three linear shape functions of triangle (a, b, c), counter-clockwise:
//   ∇φ_i = (y_j − y_k, x_k − x_j) / (2A), (i, j, k) cyclic.
std::array<geometry::Point, 3> compute_shape_gradients(geometry::Point a, geometry::Point b,
                                                       geometry::Point c);

// K_e(i, j) = A (K ∇φ_j) · ∇φ_i, the exact integral of the P1 stiffness over the triangle.
std::array<std::array<double, 3>, 3> compute_element_matrix(geometry::Point a, geometry::Point b,
                                                            geometry::Point c,
                                                            const Conductivity& k);

}  // namespace hydrodda::hydro
