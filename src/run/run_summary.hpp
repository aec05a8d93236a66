#pragma once
// The parts of summary.json that every kind of run fills the same way.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dda/system.hpp"
#include "hydro/flow_solution.hpp"
#include "hydro/fluid.hpp"
#include "hydro/permeability_field.hpp"
#include "mesh/triangle_mesh.hpp"
#include "output/summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// The name of block `block`'s material as summary.json's blocks give it; empty where the
// scenario names no material.
std::string block_material_name(const scenario::Scenario& scenario, const dda::System& system, int block);

// Title, blocks (centroid, displacement, rotation, stress, area) and measured points.
output::RunSummary summarise_mechanics(const scenario::Scenario& scenario, const dda::System& system);

// A prescribed displacement the blocks did not follow: empty when every point reached its
// ramped value to within 1% of it (or the penetration tolerance), else what was asked and what was reached at the first that
// did not (a time step so small that inertia, 2ρA/Δt², outweighs the springs that impose it
// leaves the points where they were). A run that did not do what was asked has not finished.
std::string describe_unreached_displacement(const scenario::Scenario& scenario, const dda::System& system);

// What a [[flow.region]] is measured against, which depends only on the fixed mesh and the
// boundary conditions: its triangles (none when it holds no element), the head gradient the
// boundary conditions impose on it (the unfractured case's mean gradient over it) and its
// effective conductivity along that direction in the unfractured case. Found once per model,
// and again when the boundary values change.
struct RegionReference {
  std::vector<int> triangles;
  std::optional<geometry::Point> imposed;  // none where the heads impose no gradient
  double matrix_conductivity = 0.0;        // along `imposed`, when there is one
};

// The references of the scenario's regions, in its order, from one solve of the unfractured
// case (compute_matrix_permeability) under the same boundary conditions; none without regions.
// The boundary values are those at `load_time` (scenario::find_load_times).
std::vector<RegionReference> reference_regions(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh,
                                               double load_time);

// Each [[flow.region]]'s flow and effective conductivity along its imposed gradient, with its
// conductivity in the unfractured case and their ratio, and its full effective tensor from the
// element permeabilities (m², one per triangle, isotropic or tensors; none when empty), in the scenario's
// order; none for a region that holds no element.
std::vector<std::optional<output::RegionSummary>> summarise_regions(const scenario::Scenario& scenario,
                                                                  const mesh::TriangleMesh& mesh,
                                                                  const hydro::FlowSolution& solution,
                                                                  std::span<const RegionReference> references,
                                                                  hydro::PermeabilityView permeability);

output::FlowSummary summarise_flow(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh,
                                   const hydro::FlowSolution& solution, std::span<const RegionReference> references,
                                   hydro::PermeabilityView permeability);

}  // namespace hydrodda::run
