// The flow-only transient run: the steps of plan_step_times, each a backward-Euler solve
// (hydro::DarcySolver::solve_step) with the boundary values at its end time, recorded in
// history.csv and probes.csv and, at the output times, in fluid.pvd (docs/flow.md, "Transient
// flow"; docs/output.md, "Transient runs").

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "hydro/darcy_solver.hpp"
#include "output/csv_table.hpp"
#include "output/plot_line.hpp"
#include "run/figures.hpp"
#include "run/flow_model.hpp"
#include "run/model_building.hpp"
#include "run/paraview_output.hpp"
#include "run/runs.hpp"
#include "scenario/diagnostics.hpp"
#include "run/transient_flow.hpp"
#include "scenario/load_times.hpp"

namespace hydrodda::run {

namespace {

using output::CsvTable;

// The heads of the state at t = 0 given as one head everywhere: no flow yet.
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

// What a transient run writes as it steps: history.csv, probes.csv and the fluid series.
class TransientRecorder {
 public:
  TransientRecorder(const RunContext& context, const FlowModel& model)
      : context_(context), model_(model), sites_(locate_probes(context.scenario, model.mesh())),
        history_(history_columns(context.scenario)), probes_({"time", "name", "head", "pressure"}),
        fields_(context.folder, context.scenario.output.fields) {}

  void record_state(int step, double time, double time_step, const hydro::FlowSolution& state, double head_change) {
    std::vector<std::string> row{CsvTable::cell(static_cast<long long>(step)), CsvTable::cell(time),
                                 step == 0 ? "" : CsvTable::cell(time_step),
                                 step == 0 ? "" : CsvTable::cell(static_cast<long long>(state.factorised)),
                                 step == 0 ? "" : CsvTable::cell(head_change), CsvTable::cell(state.storage_rate),
                                 CsvTable::cell(state.balance_error)};
    for (const scenario::FlowBoundaryCondition& bc : context_.scenario.flow->boundaries)
      row.push_back(CsvTable::cell(state.boundary_flow(bc.name)));
    history_.add_row(row);
    for (const ProbeSite& site : sites_) {
      probes_.add_row({CsvTable::cell(time), site.name, CsvTable::cell(value_at(site, model_.mesh(), state.head)),
                       CsvTable::cell(value_at(site, model_.mesh(), state.pressure))});
      auto& series = probe_series_[&site - sites_.data()];
      series.x.push_back(time);
      series.y.push_back(value_at(site, model_.mesh(), state.pressure));
    }
    times_.push_back(time);
    for (std::size_t b = 0; b < state.boundary_flows.size(); ++b) flows_[b].push_back(state.boundary_flows[b].flow);
    storage_rates_.push_back(state.storage_rate);
  }
  void write_fields(double time, const hydro::FlowSolution& state) {
    const std::vector<double> no_porosity;
    fields_.write_fluid(outputs_++, time, model_.mesh(), state, no_porosity, model_.permeability());
  }
  void flush() const {
    context_.folder.write("history.csv", history_.text());
    if (!sites_.empty()) context_.folder.write("probes.csv", probes_.text());
  }
  void start(const hydro::FlowSolution& state) {
    probe_series_.assign(sites_.size(), {});
    for (std::size_t i = 0; i < sites_.size(); ++i) probe_series_[i].name = sites_[i].name;
    flows_.assign(state.boundary_flows.size(), {});
  }
  // probes.* (each probe's pressure against time) and flows.* (each boundary's outward flow and
  // the rate of storage against time).
  void draw(const std::string& status) const;

 private:
  static std::vector<std::string> history_columns(const scenario::Scenario& s) {
    std::vector<std::string> columns{"step", "time", "time_step", "factorised", "head_change", "storage_rate", "balance"};
    for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) columns.push_back("flow_" + bc.name);
    return columns;
  }

  const RunContext& context_;
  const FlowModel& model_;
  std::vector<ProbeSite> sites_;
  CsvTable history_, probes_;
  ParaviewOutput fields_;
  int outputs_ = 0;
  std::vector<output::LineSeries> probe_series_;
  std::vector<double> times_, storage_rates_;
  std::vector<std::vector<double>> flows_;
};

void TransientRecorder::draw(const std::string& status) const {
  const scenario::Scenario& s = context_.scenario;
  if (s.output.figures.empty() || times_.empty()) return;
  // Time on a log axis where the run starts with steps much shorter than it (a response to a
  // step in head, fast at first): its t = 0 row is left off there.
  const bool log_time = s.flow->transient->time_step <= 0.01 * s.flow->transient->end_time;
  output::LinePlotSpec flows;
  flows.title = s.title;
  flows.warning = status;
  flows.x_label = "time (s)";
  flows.x_log = log_time;
  flows.y_label = "flow (m²/s per m)";
  for (std::size_t b = 0; b < flows_.size(); ++b)
    if (std::any_of(flows_[b].begin(), flows_[b].end(), [](double q) { return q != 0.0; }))
      flows.series.push_back({"out by " + model_.mesh().boundary_names[b], times_, flows_[b], {}});
  flows.series.push_back({"into storage", times_, storage_rates_, {}});
  for (const std::string& format : s.output.figures) {
    output::render_line_plot(context_.folder.figures() / ("flows." + format), flows);
    if (probe_series_.empty()) continue;
    output::LinePlotSpec probes;
    probes.title = s.title;
    probes.warning = status;
    probes.x_label = "time (s)";
    probes.x_log = log_time;
    probes.y_label = "pressure (Pa)";
    probes.series = probe_series_;
    output::render_line_plot(context_.folder.figures() / ("probes." + format), probes);
  }
}

double largest_change(const std::vector<double>& a, const std::vector<double>& b) {
  double change = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) change = std::max(change, std::abs(a[i] - b[i]));
  return change;
}

bool is_output_time(const scenario::TransientDefinition& t, double time) {
  return std::find(t.output_times.begin(), t.output_times.end(), time) != t.output_times.end();
}

// The state at t = 0: the steady heads of the boundary values then, or one head everywhere.
hydro::FlowSolution solve_initial_state(const scenario::Scenario& s, const FlowModel& model,
                                        hydro::DarcySolver& solver) {
  const hydro::DarcyProblem problem = build_flow_problem(*s.flow, 0.0);
  solver.set_boundary_values(problem.boundaries);
  if (!s.flow->transient->initial_head) return solver.solve(model.permeability());
  return make_uniform_state(model.mesh(), problem, solver.reference_head(), *s.flow->transient->initial_head);
}

// Nothing stores water (no material's storage where the elements are, no open gap): the heads
// would be the steady ones at every step. check refuses what it can see; the mesh shows the rest.
void refuse_without_storage(const scenario::Scenario& s, const std::vector<double>& specific_storage) {
  if (std::any_of(specific_storage.begin(), specific_storage.end(), [](double c) { return c > 0.0; })) return;
  throw scenario::ScenarioError({{s.file.string(), s.flow->transient->line, "flow.transient",
                                  "no element of the mesh stores water (no material's storage covers one, and no "
                                  "open gap between blocks holds water): give storage (1/Pa) to the materials"}});
}

}  // namespace

output::RunSummary run_transient_flow(const RunContext& context) {
  const scenario::Scenario& s = context.scenario;
  const scenario::TransientDefinition& transient = *s.flow->transient;
  std::optional<UnstoppableStage> building(context.callbacks);
  FlowModel model(s, context.mesh_cache);
  const std::optional<fractures::FractureState> no_fractures;
  const TellModelAtEnd tell_model_at_end(context.callbacks, model, no_fractures);
  const auto start = std::chrono::steady_clock::now();
  hydro::DarcySolver solver(model.mesh(), build_flow_problem(*s.flow, 0.0));
  const std::vector<double> specific_storage = compute_specific_storage(s, model.mesh(), model.blocks());
  refuse_without_storage(s, specific_storage);
  const std::vector<double> times = plan_step_times(transient, scenario::find_load_times(s));
  TransientRecorder recorder(context, model);
  hydro::FlowSolution state = solve_initial_state(s, model, solver);
  building.reset();
  recorder.start(state);
  recorder.record_state(0, 0.0, 0.0, state, 0.0);
  recorder.write_fields(0.0, state);
  recorder.flush();

  const auto summarise = [&](double time, int steps) {
    model.adopt_flow(state);
    output::RunSummary summary = model.summary(time);
    summary.iterations = steps;
    summary.time = time;
    summary.flow->storage_rate = state.storage_rate;
    summary.timings = model.timings();
    summary.timings.push_back({"transient", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    return summary;
  };
  double time = 0.0;
  std::vector<double> storage_over_step(specific_storage.size());
  for (std::size_t n = 0; n < times.size(); ++n) {
    if (context.stop_requested()) {
      recorder.flush();
      throw RunFailure(RunStatus::interrupted, fmt::format("interrupted at t = {:g} s, after {} of {} steps", time, n, times.size()),
                       summarise(time, static_cast<int>(n)));
    }
    const double step = times[n] - time;
    for (std::size_t e = 0; e < specific_storage.size(); ++e) storage_over_step[e] = specific_storage[e] / step;
    solver.set_boundary_values(build_flow_problem(*s.flow, times[n]).boundaries);
    hydro::FlowSolution next = solver.solve_step(model.permeability(), storage_over_step, hydro::MassMatrix::lumped, state.head);
    const double change = largest_change(next.head, state.head);
    state = std::move(next);
    time = times[n];
    recorder.record_state(static_cast<int>(n) + 1, time, step, state, change);
    if (is_output_time(transient, time) || n + 1 == times.size()) {
      recorder.write_fields(time, state);
      recorder.flush();
    }
    ProgressReport report;
    report.count = static_cast<long long>(n) + 1;
    report.time = time;
    report.balance_error = state.balance_error;
    report.message = fmt::format("step {}/{}: t = {:g} s, largest head change {:.3g} m", n + 1, times.size(), time, change);
    context.report(report);
  }
  output::RunSummary summary = summarise(time, static_cast<int>(times.size()));
  summary.converged = true;  // every step solved directly, to the end time
  context.write_summary(summary);
  const std::vector<double> no_porosity;
  FlowPicture picture{model.mesh(), state, no_porosity, model.permeability(), model.blocks()};
  picture.stop_requested = [&context] { return context.stop_requested(); };
  draw_figures(s, context.folder, picture);
  recorder.draw("");
  return summary;
}

}  // namespace hydrodda::run
