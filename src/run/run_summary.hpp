#pragma once
// The parts of summary.json that every kind of run fills the same way.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dda/system.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "output/summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Title, blocks (centroid, displacement, rotation, stress, area) and measured points.
output::RunSummary summarise_mechanics(const scenario::Scenario& scenario, const dda::System& system);

// A prescribed displacement the blocks did not follow: empty when every point reached its
// ramped value to within 1% of it (or the penetration tolerance), else what was asked and what was reached at the first that
// did not (a time step so small that inertia, 2ρA/Δt², outweighs the springs that impose it
// leaves the points where they were). A run that did not do what was asked has not finished.
std::string describe_unreached_displacement(const scenario::Scenario& scenario, const dda::System& system);

// The flow of the unfractured case (compute_matrix_permeability) under the same boundary
// conditions, the reference of each region's normalised conductivity; nothing when the
// scenario has no flow region to report.
std::optional<hydro::FlowSolution> solve_matrix_flow(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh);

// Each [[flow.region]]'s flow and effective conductivity along the head gradient the boundary
// conditions impose (the unfractured case's mean gradient over the region), with its
// conductivity in the unfractured case (`matrix`) along the same direction and their ratio, and
// its full effective tensor from the element permeabilities (m², one per triangle; none when
// empty), in the scenario's order; none for a region that holds no element.
std::vector<std::optional<output::RegionSummary>> summarise_regions(const scenario::Scenario& scenario,
                                                                  const mesh::TriangleMesh& mesh,
                                                                  const hydro::FlowSolution& solution,
                                                                  const std::optional<hydro::FlowSolution>& matrix,
                                                                  std::span<const double> permeability);

// Boundary flows, mass balance, and each [[flow.region]]'s flow and effective conductivity,
// with its conductivity in the unfractured case (`matrix`) and their ratio.
output::FlowSummary summarise_flow(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh,
                                   const hydro::FlowSolution& solution,
                                   const std::optional<hydro::FlowSolution>& matrix,
                                   std::span<const double> permeability);

}  // namespace hydrodda::run
