#pragma once
// What a flow solve's heads give: every node's head and pressure (by the pressure convention),
// the Darcy flux per triangle, each boundary's flow and their mass balance.

#include <Eigen/Core>

#include "hydro/darcy_assembly.hpp"
#include "hydro/flow_solution.hpp"
#include "hydro/permeability_field.hpp"

namespace hydrodda::hydro {

// The solution of the heads x over `system`'s unknowns, with the permeability `system` was
// last assembled from (its boundary flows come from that assembly).
FlowSolution make_flow_solution(const DarcyAssembler& system, const Eigen::VectorXd& x, PermeabilityView permeability);

}  // namespace hydrodda::hydro
