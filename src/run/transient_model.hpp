#pragma once
// A flow-only transient model stepped one backward-Euler step at a time: the fixed mesh and
// permeability of a FlowModel, its elements' storage, the plan of its steps and the state
// after the last one (docs/flow.md, "Transient flow"). run_transient_flow steps it to the end
// and records each step; hydrodda.Simulation steps it by hand. Both take the same steps, so a
// model stepped by hand reaches the program's values to the last digit.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hydro/darcy_solver.hpp"
#include "hydro/flow_solution.hpp"
#include "output/summary.hpp"
#include "run/flow_model.hpp"
#include "run/transient_flow.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// A probe's head (m) and pressure (Pa) at the model's time: a row of probes.csv.
struct ProbeReading {
  std::string name;
  double head = 0.0;
  double pressure = 0.0;
};

class TransientModel {
 public:
  // Meshes and builds the model and solves its state at t = 0 (the steady heads of the
  // boundary values then, or initial_head everywhere). Throws scenario::ScenarioError when no
  // element stores water or a probe lies outside the mesh.
  explicit TransientModel(const scenario::Scenario& scenario,
                          const std::optional<std::filesystem::path>& mesh_cache = std::nullopt);

  // Takes up the state after `steps` of the plan's steps (a checkpoint's): its time is the
  // plan's, and the solver is given the last step's matrix, so that the next step factors (or
  // not) as it would have in a run that was never stopped. Throws std::invalid_argument when
  // the state does not fit the model (its heads' count, its step number, its time).
  void resume(int steps, double time, hydro::FlowSolution state);

  // The next step of the plan; throws std::logic_error when the end time is reached.
  void step();

  bool finished() const { return steps_ == static_cast<int>(times_.size()); }
  int steps_taken() const { return steps_; }
  int step_count() const { return static_cast<int>(times_.size()); }
  const std::vector<double>& step_times() const { return times_; }  // t_1 … end_time (plan_step_times)
  double time() const { return steps_ == 0 ? 0.0 : times_[steps_ - 1]; }
  // The last step's length, and the largest change of a node's head over it (m); 0 before any.
  double last_time_step() const { return last_step_; }
  double last_head_change() const { return last_change_; }
  // An output time, or the end time: the fields are written there.
  bool at_output_time() const;

  const hydro::FlowSolution& state() const { return state_; }
  const FlowModel& model() const { return model_; }
  FlowModel& model() { return model_; }
  const std::vector<ProbeSite>& probe_sites() const { return sites_; }
  std::vector<ProbeReading> read_probes() const;
  // summary.json's content for the state now (no timings): the flow's, the time, the steps
  // taken as `iterations`, the rate of storage; `converged` left false (the run's to say).
  output::RunSummary summary();

 private:
  const scenario::TransientDefinition& transient() const { return *model_.scenario().flow->transient; }
  hydro::FlowSolution solve_step_to(int n);

  FlowModel model_;
  hydro::DarcySolver solver_;
  std::vector<double> specific_storage_;   // S_s per element (1/m)
  std::vector<double> storage_over_step_;  // S_s/Δt of the step being solved
  std::vector<double> times_;
  std::vector<ProbeSite> sites_;
  hydro::FlowSolution state_;
  int steps_ = 0;
  double last_step_ = 0.0, last_change_ = 0.0;
};

}  // namespace hydrodda::run
