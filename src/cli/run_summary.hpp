#pragma once
// The parts of summary.json that every kind of run fills the same way.

#include "dda/system.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "output/summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::cli {

// Title, blocks (centroid, displacement, rotation, stress, area) and measured points.
output::RunSummary summarise_mechanics(const scenario::Scenario& scenario, const dda::System& system);

// Boundary flows, mass balance, and each [[flow.region]]'s flow and effective conductivity.
output::FlowSummary summarise_flow(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh,
                                   const hydro::FlowSolution& solution);

}  // namespace hydrodda::cli
