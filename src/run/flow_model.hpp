#pragma once
// A flow-only model: the fixed mesh, the blocks' geometry and the permeability it gives, and
// one steady Darcy solve. It writes no file; run() drives it into a run folder.

#include <filesystem>
#include <optional>
#include <vector>

#include "geometry/polygon.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "output/summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

class FlowModel {
 public:
  // Meshes the domain (or reads mesh.file), cuts the blocks and gives every element its
  // permeability: a flow region's fixed value, else the porosity law's from the space the blocks
  // leave open. Throws scenario::ScenarioError for a mesh.file that cannot be used.
  // `mesh_cache`: a folder of meshes shared with other runs (build_mesh).
  explicit FlowModel(const scenario::Scenario& scenario,
                     const std::optional<std::filesystem::path>& mesh_cache = std::nullopt);

  // The heads under the scenario's boundary conditions.
  const hydro::FlowSolution& solve();
  // New [[flow.boundary]] conditions for the next solve(); the last solution is dropped.
  void set_flow_boundaries(std::vector<scenario::FlowBoundaryCondition> boundaries);

  const scenario::Scenario& scenario() const { return scenario_; }
  const mesh::TriangleMesh& mesh() const { return mesh_; }
  const std::vector<geometry::Polygon>& blocks() const { return blocks_; }
  const std::vector<double>& permeability() const { return permeability_; }  // per element
  const hydro::FlowSolution& flow() const { return solution_; }  // empty before solve()
  // A transient run's state, solved outside (run_transient_flow), as the flow summary() reads.
  void adopt_flow(hydro::FlowSolution solution) { solution_ = std::move(solution); }
  // summary.json's title and flow (boundary flows, balance, regions); no timings. The regions'
  // references take the boundary values at the last row of the tables, or at `time` (a
  // transient run's).
  output::RunSummary summary() const;
  output::RunSummary summary(double time) const;
  // Seconds per phase: mesh, permeability, flow.
  const std::vector<output::NamedValue>& timings() const { return timings_; }

 private:
  scenario::Scenario scenario_;
  std::vector<output::NamedValue> timings_;
  mesh::TriangleMesh mesh_;
  std::vector<geometry::Polygon> blocks_;
  std::vector<double> permeability_;
  hydro::FlowSolution solution_;
};

}  // namespace hydrodda::run
