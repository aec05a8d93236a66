#pragma once
// A flow-only transient run ([flow.transient]): backward-Euler steps of
//   S_s ∂h/∂t − ∇·(K ∇h) = 0,  S_s = ρ_w g S per element from its material's storage S (1/Pa),
// on the fixed mesh and permeability of a flow-only model, from the initial heads to end_time
// (docs/flow.md, "Transient flow"). The pieces a run is made of, each testable alone: the plan
// of its steps, its probes, and the run itself (run_transient_flow, dispatched by run_flow).

#include <array>
#include <string>
#include <vector>

#include "geometry/polygon.hpp"
#include "hydro/darcy_assembly.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Each step is this much longer than the one before, up to max_time_step: the heads after a
// change vary on a time scale of the time since it, so steps in proportion to it keep backward
// Euler's error alike from step to step (docs/flow.md, "Time steps").
inline constexpr double kTimeStepGrowth = 1.2;

// The times the run steps to, t_1 < t_2 < … = end_time: t_1 = time_step, each nominal step
// kTimeStepGrowth times the last up to max_time_step, and a step that would pass an output time,
// one of `row_times` (the boundary tables' rows, where their values turn) or the end shortened
// to end there exactly (the nominal step grows on from its own length).
std::vector<double> plan_step_times(const scenario::TransientDefinition& transient,
                                    const std::vector<double>& row_times = {});

// Per element, its specific storage in head (1/m): the rock's and the open gaps' water's,
//   S_s = ρ_w g [(1 − f) S + f c_w],
// f = A_fracture/A_element the part of it no block covers (the porosity mapping's), S the
// storage of its material (scenario::find_material_at at its centroid; 0 where no material
// holds it), c_w the fluid's compressibility: water in a gap between blocks held still stores
// by its own compressibility alone, a c_w per unit volume of gap (docs/flow.md, "Transient flow").
std::vector<double> compute_specific_storage(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh,
                                             const std::vector<geometry::Polygon>& blocks);

// The state at t = 0 given as one head everywhere (flow.transient.initial_head): no flow yet,
// the pressures by the problem's convention about `reference_head`.
hydro::FlowSolution make_uniform_state(const mesh::TriangleMesh& mesh, const hydro::DarcyProblem& problem,
                                       double reference_head, double head);

// A probe's place in the mesh: the triangle that holds its point and the point's barycentric
// weights there, with which P1 values are read exactly.
struct ProbeSite {
  std::string name;
  int triangle = -1;
  std::array<double, 3> weights{};
};

// Throws scenario::ScenarioError (flow.probe.point, its line) for a point outside the mesh.
std::vector<ProbeSite> locate_probes(const scenario::Scenario& scenario, const mesh::TriangleMesh& mesh);

// The P1 field `nodal` (one value per node) at a probe.
double value_at(const ProbeSite& site, const mesh::TriangleMesh& mesh, const std::vector<double>& nodal);

}  // namespace hydrodda::run
