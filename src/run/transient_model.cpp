#include "run/transient_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "run/model_building.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/load_times.hpp"

namespace hydrodda::run {

hydro::FlowSolution make_uniform_state(const mesh::TriangleMesh& mesh, const hydro::DarcyProblem& problem,
                                       double reference_head, double head) {
  hydro::FlowSolution state;
  state.reference_head = reference_head;
  state.head.assign(mesh.nodes.size(), head);
  state.pressure.resize(mesh.nodes.size());
  const double rho_g = problem.fluid.unit_weight();
  for (int v = 0; v < mesh.node_count(); ++v)
    state.pressure[v] = problem.pressure == hydro::PressureConvention::overpressure ? rho_g * (head - reference_head)
                                                                                    : rho_g * (head - mesh.nodes[v].y);
  state.flux.assign(mesh.triangles.size(), {0.0, 0.0});
  for (const std::string& name : mesh.boundary_names) state.boundary_flows.push_back({name, 0.0});
  return state;
}

namespace {

// Nothing stores water (no material's storage where the elements are, no open gap): the heads
// would be the steady ones at every step. check refuses what it can see; the mesh shows the rest.
void refuse_without_storage(const scenario::Scenario& s, const std::vector<double>& specific_storage) {
  if (std::any_of(specific_storage.begin(), specific_storage.end(), [](double c) { return c > 0.0; })) return;
  throw scenario::ScenarioError({{s.file.string(), s.flow->transient->line, "flow.transient",
                                  "no element of the mesh stores water (no material's storage covers one, and no "
                                  "open gap between blocks holds water): give storage (1/Pa) to the materials"}});
}

double largest_change(const std::vector<double>& a, const std::vector<double>& b) {
  double change = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) change = std::max(change, std::abs(a[i] - b[i]));
  return change;
}

}  // namespace

TransientModel::TransientModel(const scenario::Scenario& s, const std::optional<std::filesystem::path>& mesh_cache)
    : model_(s, mesh_cache), solver_(model_.mesh(), build_flow_problem(*s.flow, 0.0)) {
  const scenario::Scenario& own = model_.scenario();
  specific_storage_ = compute_specific_storage(own, model_.mesh(), model_.blocks());
  refuse_without_storage(own, specific_storage_);
  storage_over_step_.resize(specific_storage_.size());
  times_ = plan_step_times(transient(), scenario::find_load_times(own));
  sites_ = locate_probes(own, model_.mesh());
  // The state at t = 0: the steady heads of the boundary values then, or one head everywhere.
  const hydro::DarcyProblem problem = build_flow_problem(*own.flow, 0.0);
  solver_.set_boundary_values(problem.boundaries);
  state_ = transient().initial_head
               ? make_uniform_state(model_.mesh(), problem, solver_.reference_head(), *transient().initial_head)
               : solver_.solve(model_.permeability());
}

bool TransientModel::at_output_time() const {
  if (steps_ == 0) return false;
  const std::vector<double>& outputs = transient().output_times;
  return finished() || std::find(outputs.begin(), outputs.end(), time()) != outputs.end();
}

hydro::FlowSolution TransientModel::solve_step_to(int n) {
  const double start = n == 0 ? 0.0 : times_[n - 1];
  const double step = times_[n] - start;
  for (std::size_t e = 0; e < specific_storage_.size(); ++e) storage_over_step_[e] = specific_storage_[e] / step;
  solver_.set_boundary_values(build_flow_problem(*model_.scenario().flow, times_[n]).boundaries);
  return solver_.solve_step(model_.permeability(), storage_over_step_, hydro::MassMatrix::lumped, state_.head);
}

void TransientModel::step() {
  if (finished()) throw std::logic_error("step(): the transient run has reached its end_time");
  hydro::FlowSolution next = solve_step_to(steps_);
  last_step_ = times_[steps_] - time();
  last_change_ = largest_change(next.head, state_.head);
  state_ = std::move(next);
  ++steps_;
}

void TransientModel::resume(int steps, double time, hydro::FlowSolution state) {
  if (steps < 0 || steps > step_count())
    throw std::invalid_argument("the saved state is after step " + std::to_string(steps) + " of a plan of " +
                                std::to_string(step_count()));
  if ((steps == 0 ? 0.0 : times_[steps - 1]) != time)
    throw std::invalid_argument("the saved state's time is not the plan's at its step");
  if (state.head.size() != model_.mesh().nodes.size())
    throw std::invalid_argument("the saved heads are not one per node of the mesh");
  // The last step solved again from the saved heads, its answer dropped: the solver then holds
  // that step's factor, as it did in the run that was stopped (the factor depends on the step
  // length and the permeability alone, not on the heads or the boundary values).
  if (steps > 0) {
    state_ = state;
    (void)solve_step_to(steps - 1);
    last_step_ = times_[steps - 1] - (steps == 1 ? 0.0 : times_[steps - 2]);
  }
  state_ = std::move(state);
  steps_ = steps;
}

std::vector<ProbeReading> TransientModel::read_probes() const {
  std::vector<ProbeReading> readings;
  for (const ProbeSite& site : sites_)
    readings.push_back({site.name, value_at(site, model_.mesh(), state_.head), value_at(site, model_.mesh(), state_.pressure)});
  return readings;
}

output::RunSummary TransientModel::summary() {
  model_.adopt_flow(state_);
  output::RunSummary summary = model_.summary(time());
  summary.iterations = steps_;
  summary.time = time();
  summary.flow->storage_rate = state_.storage_rate;
  return summary;
}

}  // namespace hydrodda::run
