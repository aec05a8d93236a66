#pragma once
// The seepage force of Biot's effective stress. The pore pressure p in a block of Biot
// coefficient α loads its skeleton with the body force −α ∇p inside it and the traction
// −(1 − α) p n on its faces (pressure_forces.hpp); the contact forces are then effective.
// α = 0 is the paper's rule (the faces take all the pressure: the blocks respond to total
// stress); α = 1 is Terzaghi's effective stress.
//
// For the P1 field ∇p is constant in each element, so over the part of block b in element e
// (area A, centroid c, found by the porosity clip) the force is f = −α A ∇p_e at c, and DDA's
// ∫ Tᵀ f dA over the part is exactly Tᵀ(c) f: T is affine in x. It reaches all six unknowns
// (translations, rotation and strains), not the translations only.
//
// The block's seepage force is handed to DDA as vertex forces with the same resultant and first
// moments, which is all DDA sees of a load (force_moments.hpp).
//
// Net force and moment are the same for every α (divergence theorem: ∫_B ∇p dA = ∮ p n ds for
// the continuous P1 p, when the block lies in the fluid mesh); only the strain load differs,
// by α ∫_B p dA on εx and εy, which is what keeps a uniformly pressurised joint shut at α = 1.

#include <span>
#include <vector>

#include "coupling/force_moments.hpp"
#include "coupling/porosity.hpp"
#include "geometry/point.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::coupling {

using geometry::Point;

// forces[b][v] on vertex v of block b: the seepage force of the pieces of every block
// (pieces' blocks index `blocks`, their elements `pressure_gradients`), times biot[b].
std::vector<std::vector<Point>> compute_seepage_forces(std::span<const geometry::Polygon> blocks,
                                                       const BlockPieces& pieces,
                                                       std::span<const Point> pressure_gradients,
                                                       std::span<const double> biot);

}  // namespace hydrodda::coupling
