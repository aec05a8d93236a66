#pragma once
// Flow through a region of the mesh and its effective conductivity.
//
// Definition (for a region R of area A, a flow direction d, |d| = 1):
//   L = extent of R along d,  W = extent of R across d (from its nodes),
//   Q      = (1/L) ∫_R q·d dA               flow through R (m²/s per metre thickness),
//   G      = −(1/A) ∫_R ∇h·d dA             mean head gradient along d,
//   K_eff  = Q / (W G)                      effective conductivity (m/s).
// For a rectangle aligned with d (A = L W) K_eff = ⟨q·d⟩ / ⟨−∂h/∂d⟩: the harmonic mean of
// layers in series and the arithmetic mean of layers in parallel, as Darcy's law for the
// whole block demands.

#include <optional>
#include <span>

#include "geometry/point.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

struct RegionFlow {
  geometry::Point direction;      // d
  double area = 0.0;              // A
  double length = 0.0;            // L
  double width = 0.0;             // W
  double flow = 0.0;              // Q
  double head_gradient = 0.0;     // G
  double effective_conductivity = 0.0;  // K_eff; NaN when G = 0
  // −(1/A) ∫_R ∇h dA: the mean head gradient's vector (its component along d is G). In the
  // unfractured case it points along the gradient the boundary conditions impose.
  geometry::Point mean_head_gradient;
};

// Over the given triangles. Without a direction, d is the direction of the region's mean
// flux ∫ q dA (the x axis when no water flows). Throws on an empty selection.
RegionFlow compute_region_flow(const mesh::TriangleMesh& mesh, const FlowSolution& solution,
                               std::span<const int> triangles,
                               std::optional<geometry::Point> direction = std::nullopt);

}  // namespace hydrodda::hydro
