#pragma once
// What to tell a user whose flow solve failed, in the model's terms: the permeability contrast
// the solve met (the largest and smallest principal permeability, and where), and which of two
// faults it is where either is true: a part of the mesh that touches no fixed-head boundary
// (disconnected: its head is undetermined), or one that reaches a fixed-head boundary only
// through elements whose permeability is lost to round-off beside the largest (ill-conditioned).
// No linear-algebra message reaches a user.

#include <span>
#include <string>

#include "hydro/linear_solver.hpp"
#include "hydro/permeability_field.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

// A flow solve that failed (its matrix could not be factored, or its heads came out not
// finite); what() says so in the model's terms (describe_flow_failure).
class FlowSolveFailed : public SingularSystem {
 public:
  using SingularSystem::SingularSystem;
};

// Permeability below this fraction of the largest is lost to round-off beside it in a sum of
// element matrices (double precision carries about 16 digits).
inline constexpr double kLostToRoundOff = 1e-16;

// "the flow solve failed (its matrix could not be factored): the permeability spans 1e-20 m²
// (element 12 at (0.5, 0.25)) to 0.003 m² (element 40 at (1.5, 0.75)), a contrast of 3e+17,
// past the 1e16 that double precision resolves; the system is ill-conditioned, not
// disconnected: the part of the mesh around node 7 (1, 0.5) reaches a fixed-head boundary only
// through elements whose permeability is under 1e-16 of the largest, ..." (`fixed_head`: NaN
// where free, one per node); or "...; the part of the mesh around node 3 (2, 0) touches no
// fixed-head boundary: its head is undetermined".
std::string describe_flow_failure(const mesh::TriangleMesh& mesh, PermeabilityView permeability,
                                  std::span<const double> fixed_head, const std::string& what_failed);

}  // namespace hydrodda::hydro
