#pragma once
// A coupled model: the fixed fluid mesh, the DDA system and the staggered loop that joins them,
// owned together and advanced one coupling pass at a time. It writes no file; run() drives it
// into a run folder (history, ParaView series, checkpoint after every pass).

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "coupling/staggered_loop.hpp"
#include "dda/system.hpp"
#include "hydro/flow_solution.hpp"
#include "mesh/triangle_mesh.hpp"
#include "output/summary.hpp"
#include "run/run_summary.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// Everything a later pass reads, as plain data: what checkpoint.bin holds of the engines.
struct CoupledState {
  dda::SystemState mechanics;
  coupling::LoopState coupling;
};

class CoupledModel {
 public:
  // Meshes the domain (or reads mesh.file), builds the DDA system and the loop, and solves the
  // unfractured case once (the reference of the regions' normalised conductivity). Throws
  // scenario::ScenarioError for what only building shows.
  // `mesh_cache`: a folder of meshes shared with other runs (build_mesh).
  // `added_refinement`: [[mesh.refine]] points to mesh with besides the scenario's own (the
  // wedge tips of mesh.refine_tips); the model's scenario() holds them all.
  explicit CoupledModel(const scenario::Scenario& scenario,
                        const std::optional<std::filesystem::path>& mesh_cache = std::nullopt,
                        std::span<const scenario::MeshRefinePoint> added_refinement = {});
  // The loop keeps references to the mesh and the system: the model stays where it was built.
  CoupledModel(const CoupledModel&) = delete;
  CoupledModel& operator=(const CoupledModel&) = delete;

  // One pass: porosity → permeability → flow → pressures → vertex forces → DDA steps
  // (coupling::StaggeredLoop::run_pass). A pass the stop request abandons
  // (coupling::PassInterrupted, rethrown) leaves the model at its last finished pass, or as
  // built. Any other failure leaves the engines where it happened, until abandon_pass().
  coupling::PassReport run_pass() { return loop_->run_pass(); }
  // Passes until `limits` or an end the passes measure, `observer` told after each
  // (coupling::StaggeredLoop::run); a pass that throws is rethrown, as by run_pass().
  coupling::LoopResult run(const coupling::LoopLimits& limits, coupling::PassObserver& observer) {
    return loop_->run(limits, observer);
  }
  // After a pass that failed: the model back at its last finished pass (or as built), its
  // fields and heads included, so that its summary describes that pass; nothing when no pass
  // is under way.
  void abandon_pass() { loop_->abandon_pass(); }
  // Asked before every DDA step of a pass; unset: never.
  void set_stop_request(std::function<bool()> stop_requested) { stop_requested_ = std::move(stop_requested); }

  // A loading path scripted between passes, taken from the next pass on: new values of the
  // [[flow.boundary]] conditions (the same boundaries and kinds; throws std::invalid_argument
  // otherwise), and new [[mechanics.traction]] loads (placed on the blocks as built; throws
  // scenario::ScenarioError for a boundary on which no block edge lies). The unfractured
  // reference the regions' conductivity is normalised by is solved again for new heads.
  void set_flow_boundaries(std::vector<scenario::FlowBoundaryCondition> boundaries);
  void set_tractions(std::vector<scenario::Traction> tractions);

  // Load steps (docs/scenario.md, "Loads over time"): the loads given as (time, value) tables
  // are read at the load time of step k (1 … load_steps()), the k-th of the tables' row times,
  // from the next pass on; each step's passes run to convergence before the next starts. One
  // step, at time 0, when every load is a constant.
  int load_steps() const { return load_times_.empty() ? 1 : static_cast<int>(load_times_.size()); }
  int load_step() const { return load_step_; }
  double load_time() const { return load_times_.empty() ? 0.0 : load_times_[load_step_ - 1]; }
  bool has_load_tables() const { return !load_times_.empty(); }
  void start_load_step(int step);

  // A coupled transient run ([flow.transient]; coupling::StaggeredLoop::begin_time_step): the
  // heads at t = 0 (flow.transient.initial_head: one head everywhere, or the steady heads on
  // the blocks as built), then each step from `time` to `time + time_step`, its passes its
  // fixed-stress iterations under the boundary values and loads of its end time.
  bool transient() const { return scenario_.flow && scenario_.flow->transient; }
  void start_in_time();
  void begin_time_step(double time, double time_step);
  // Steady passes from the state now under the boundary values and loads of `time` (a time
  // step that failed, asking whether its loads have an equilibrium at all).
  void begin_steady_at(double time);

  // The state after the last finished pass (as built before the first), and its restoration
  // into a model built from the same scenario (continuing a run); throws std::invalid_argument
  // when it does not fit.
  CoupledState export_state() const { return {loop_->mechanics_state(), loop_->export_state()}; }
  void import_state(const CoupledState& state);

  int iterations() const { return loop_->iterations(); }
  const scenario::Scenario& scenario() const { return scenario_; }
  const mesh::TriangleMesh& mesh() const { return mesh_; }
  const dda::System& mechanics() const { return *system_; }
  const coupling::StaggeredLoop& loop() const { return *loop_; }
  std::vector<geometry::Polygon> block_polygons() const;

  // summary.json's blocks, measured points and flow (once a pass has solved it), iterations =
  // passes finished; no timings.
  output::RunSummary summary() const;
  // Each [[flow.region]]'s flow and effective conductivity now (summarise_regions, without the
  // tensor, which summary() gives); needs a
  // finished pass.
  std::vector<std::optional<output::RegionSummary>> region_flows() const;
  // Seconds per phase: mesh, porosity, flow, forces, mechanics.
  std::vector<output::NamedValue> timings() const;
 private:
  scenario::Scenario scenario_;
  double mesh_seconds_ = 0.0;
  mesh::TriangleMesh mesh_;
  std::vector<dda::BlockDefinition> initial_blocks_;  // where the tractions' edges are found
  std::optional<dda::System> system_;
  std::optional<coupling::StaggeredLoop> loop_;
  // What each flow region is measured against (the unfractured case): found once, and again for
  // new boundary values.
  std::vector<RegionReference> region_references_;
  std::function<bool()> stop_requested_;
  std::vector<double> load_times_;  // scenario::find_load_times
  int load_step_ = 1;
};

}  // namespace hydrodda::run
