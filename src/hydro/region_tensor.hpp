#pragma once
// The full effective conductivity tensor of a region, by two auxiliary flow solves on it.
//
// Homogenisation with linear (affine) head conditions on the region's boundary (Hill 1963;
// Renard & de Marsily 1997, §4): for each unit gradient e_i, solve
//   ∇·(K ∇u_i) = 0 in R,   u_i = x·e_i on ∂R,
// so that the region's mean head gradient is e_i exactly (⟨∇u_i⟩ = (1/A) ∮ u_i n ds = e_i), and
//   K_eff,ij = (1/A) ∫_R ∇u_i · K ∇u_j dA,
// which by Hill's lemma (∇·(K∇u_j) = 0 and u_i affine on ∂R) equals e_i · ⟨K ∇u_j⟩: the mean
// flux per unit mean gradient. The energy form makes the tensor symmetric and positive by
// construction. Linear conditions are the upper bound of the usual three (linear ≥ periodic ≥
// uniform flux): they hold the head linear along the region's sides, so a fracture that ends
// inside the region is not short-circuited through the boundary but a layer in series feels
// its sides held. For a region crossed by parallel fractures along e_i, K_eff,ii is the
// arithmetic mean, exactly as the flow along them gives it.
// Why two solves and not the run's own flow: the run's boundary conditions set one gradient;
// the second column of the tensor needs a second, independent one on the same conductivities.

#include <array>
#include <span>

#include "geometry/point.hpp"
#include "hydro/p1_element.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

struct EffectiveTensor {
  Conductivity tensor;                  // K_eff (m/s): xx, xy, yy
  std::array<double, 2> principal{};    // eigenvalues, largest first (m/s)
  // Unit eigenvectors of the principal values, in the same order (first component ≥ 0, or
  // along +y for a vertical one).
  std::array<geometry::Point, 2> directions{};
};

// Over the given triangles (a connected set whose boundary has at least two nodes not on one
// line), with one conductivity per mesh triangle (m/s). Throws when the selection is empty.
EffectiveTensor compute_region_tensor(const mesh::TriangleMesh& mesh, std::span<const Conductivity> conductivity,
                                      std::span<const int> triangles);

// Eigenvalues and unit eigenvectors of a symmetric 2×2 tensor, largest first.
EffectiveTensor principal_axes(const Conductivity& tensor);

}  // namespace hydrodda::hydro
