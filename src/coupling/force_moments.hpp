#pragma once
// A load distributed over a block reaches DDA only through its resultant and its first
// moments: the displacement T·D is affine in x, so Σ Tᵀ(x_k) F_k (or ∫ Tᵀ f) depends on Σ F_k
// and Σ (x_k − x0) ⊗ F_k alone. Any load can therefore be handed to DDA exactly as forces at
// the block's vertices with the same resultant and first moments.

#include <vector>

#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::coupling {

using geometry::Point;

// Resultant Σ F_k and first moments Σ (x_k − origin)_i F_k,j of a set of forces.
struct ForceMoments {
  Point origin;
  Point resultant;
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;  // Σ X F_x, Σ X F_y, Σ Y F_x, Σ Y F_y
  void add(Point at, Point force);
  // A force along the segment a→b of magnitude linear from q_a to q_b (per metre), direction n.
  void add_along(Point a, Point b, double q_a, double q_b, Point n);
};

// The mean of a polygon's vertices: the origin distribute_to_vertices wants moments about.
Point vertex_mean(const geometry::Polygon& polygon);

// Forces at the polygon's vertices (three or more, not all on one line) with the resultant and
// first moments of `moments` (taken about vertex_mean(polygon)): F_v = R/n + M S⁻¹ (x_v − m),
// S = Σ (x_v − m)(x_v − m)ᵀ, the smallest such set (least squares).
std::vector<Point> distribute_to_vertices(const geometry::Polygon& polygon, const ForceMoments& moments);

}  // namespace hydrodda::coupling
