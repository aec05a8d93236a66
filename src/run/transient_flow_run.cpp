// The flow-only transient run: a TransientModel stepped through its plan, each step recorded in
// history.csv and probes.csv and, at the output times, in fluid.pvd and checkpoint.bin; an
// interrupted run leaves the checkpoint of its last finished step, from which `run --resume`
// continues bit for bit (docs/flow.md, "Transient flow"; docs/output.md, "Transient runs").

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

#include "output/csv_table.hpp"
#include "output/plot_line.hpp"
#include "output/time_axis.hpp"
#include "run/figures.hpp"
#include "run/paraview_output.hpp"
#include "run/runs.hpp"
#include "run/transient_model.hpp"

namespace hydrodda::run {

namespace {

using output::CsvTable;

// What a transient run writes as it steps: history.csv, probes.csv, the fluid series and the
// checkpoint, whose record (output::TransientCheckpoint) holds all of it so far.
class TransientRecorder {
 public:
  TransientRecorder(const RunContext& context, const TransientModel& model)
      : context_(context), model_(model), fields_(context.folder, context.scenario.output.fields) {}

  // A new run: the scenario's copy for resume, and the state at t = 0.
  void start() {
    record_.scenario_hash = output::hash_text(context_.scenario_text);
    record_.scenario_file = std::filesystem::absolute(context_.scenario.file).string();
    record_.input_files = hash_input_files(context_.scenario);
    record_.boundary_flows.assign(model_.state().boundary_flows.size(), {});
    record_.probe_pressures.assign(model_.probe_sites().size(), {});
    context_.folder.write("scenario.toml", context_.scenario_text);
    record_state();
    write_fields();
    flush();
  }
  // A continued run: what its checkpoint recorded, the fluid files listed again.
  void resume_from(const output::TransientCheckpoint& saved) {
    record_ = saved;
    fields_.list_written_fluid(record_.output_times);
  }
  void record_state();
  void write_fields() {
    fields_.write_fluid(static_cast<int>(record_.output_times.size()), model_.time(), model_.model().mesh(),
                        model_.state(), {}, model_.model().permeability());
    record_.output_times.push_back(model_.time());
  }
  void flush() const;
  // history.csv and probes.csv, then checkpoint.bin of the state now.
  void save_checkpoint();
  // probes.* (each probe's pressure against time) and flows.* (each boundary's outward flow and
  // the rate of storage against time).
  void draw(const std::string& status) const;

 private:
  const RunContext& context_;
  const TransientModel& model_;
  ParaviewOutput fields_;
  output::TransientCheckpoint record_;
};

void TransientRecorder::record_state() {
  const hydro::FlowSolution& state = model_.state();
  const int step = model_.steps_taken();
  std::vector<std::string> row{CsvTable::cell(static_cast<long long>(step)), CsvTable::cell(model_.time()),
                               step == 0 ? "" : CsvTable::cell(model_.last_time_step()),
                               step == 0 ? "" : CsvTable::cell(static_cast<long long>(state.factorised)),
                               step == 0 ? "" : CsvTable::cell(model_.last_head_change()),
                               CsvTable::cell(state.storage_rate), CsvTable::cell(state.balance_error)};
  for (const scenario::FlowBoundaryCondition& bc : context_.scenario.flow->boundaries)
    row.push_back(CsvTable::cell(state.boundary_flow(bc.name)));
  record_.history.push_back(std::move(row));
  const std::vector<ProbeReading> readings = model_.read_probes();
  for (std::size_t p = 0; p < readings.size(); ++p) {
    record_.probes.push_back({CsvTable::cell(model_.time()), readings[p].name, CsvTable::cell(readings[p].head),
                              CsvTable::cell(readings[p].pressure)});
    record_.probe_pressures[p].push_back(readings[p].pressure);
  }
  record_.times.push_back(model_.time());
  for (std::size_t b = 0; b < state.boundary_flows.size(); ++b)
    record_.boundary_flows[b].push_back(state.boundary_flows[b].flow);
  record_.storage_rates.push_back(state.storage_rate);
  record_.steps = step;
  record_.time = model_.time();
  record_.time_step = model_.last_time_step();
}

void TransientRecorder::flush() const {
  std::vector<std::string> columns{"step", "time", "time_step", "factorised", "head_change", "storage_rate", "balance"};
  for (const scenario::FlowBoundaryCondition& bc : context_.scenario.flow->boundaries) columns.push_back("flow_" + bc.name);
  CsvTable history(columns);
  for (const auto& row : record_.history) history.add_row(row);
  context_.folder.write("history.csv", history.text());
  if (model_.probe_sites().empty()) return;
  CsvTable probes({"time", "name", "head", "pressure"});
  for (const auto& row : record_.probes) probes.add_row(row);
  context_.folder.write("probes.csv", probes.text());
}

void TransientRecorder::save_checkpoint() {
  flush();
  record_.state = model_.state();  // copied here, not at each step: megabytes on a large mesh
  context_.folder.write("checkpoint.bin", output::encode_transient_checkpoint(record_));
}

void TransientRecorder::draw(const std::string& status) const {
  const scenario::Scenario& s = context_.scenario;
  if (s.output.figures.empty() || record_.times.empty()) return;
  // Time on a log axis where the run starts with steps much shorter than it (a response to a
  // step in head, fast at first): its t = 0 row is left off there.
  const bool log_time = s.flow->transient->time_step <= 0.01 * s.flow->transient->end_time;
  const std::vector<double>& times = record_.times;
  output::LinePlotSpec flows;
  flows.title = s.title;
  flows.warning = status;
  flows.x_log = log_time;
  flows.y_label = "flow (m²/s per m)";
  for (std::size_t b = 0; b < record_.boundary_flows.size(); ++b) {
    const std::vector<double>& q = record_.boundary_flows[b];
    if (std::any_of(q.begin(), q.end(), [](double v) { return v != 0.0; }))
      flows.series.push_back({"out by " + model_.model().mesh().boundary_names[b], times, q, {}});
  }
  flows.series.push_back({"into storage", times, record_.storage_rates, {}});
  output::put_time_axis(flows);
  for (const std::string& format : s.output.figures) {
    output::render_line_plot(context_.folder.figures() / ("flows." + format), flows);
    if (model_.probe_sites().empty()) continue;
    output::LinePlotSpec probes;
    probes.title = s.title;
    probes.warning = status;
    probes.x_log = log_time;
    probes.y_label = "pressure (Pa)";
    for (std::size_t p = 0; p < model_.probe_sites().size(); ++p)
      probes.series.push_back({model_.probe_sites()[p].name, times, record_.probe_pressures[p], {}});
    output::put_time_axis(probes);
    output::render_line_plot(context_.folder.figures() / ("probes." + format), probes);
  }
}

// The model of a run, or of a run continued from its checkpoint at the step it saved.
std::unique_ptr<TransientModel> build_model(const RunContext& context) {
  auto model = std::make_unique<TransientModel>(context.scenario, context.mesh_cache);
  if (const output::TransientCheckpoint* saved = context.resume_transient)
    model->resume(saved->steps, saved->time, saved->state);
  return model;
}

}  // namespace

output::RunSummary run_transient_flow(const RunContext& context) {
  std::optional<UnstoppableStage> building(context.callbacks);
  const std::unique_ptr<TransientModel> model = build_model(context);
  const std::optional<fractures::FractureState> no_fractures;
  const TellModelAtEnd tell_model_at_end(context.callbacks, model->model(), no_fractures);
  const auto start = std::chrono::steady_clock::now();
  TransientRecorder recorder(context, *model);
  if (context.resume_transient) recorder.resume_from(*context.resume_transient);
  else recorder.start();
  building.reset();

  const auto summarise = [&] {
    output::RunSummary summary = model->summary();
    summary.timings = model->model().timings();
    summary.timings.push_back({"transient", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    return summary;
  };
  while (!model->finished()) {
    if (context.stop_requested()) {
      recorder.save_checkpoint();  // the last finished step's state, to resume from
      throw RunFailure(RunStatus::interrupted,
                       fmt::format("interrupted at t = {:g} s, after {} of {} steps", model->time(),
                                   model->steps_taken(), model->step_count()),
                       summarise());
    }
    model->step();
    recorder.record_state();
    if (model->at_output_time()) {
      recorder.write_fields();
      recorder.save_checkpoint();
    }
    ProgressReport report;
    report.count = model->steps_taken();
    report.time = model->time();
    report.balance_error = model->state().balance_error;
    report.message = fmt::format("step {}/{}: t = {:g} s, largest head change {:.3g} m", model->steps_taken(),
                                 model->step_count(), model->time(), model->last_head_change());
    context.report(report);
  }
  output::RunSummary summary = summarise();
  summary.converged = true;  // every step solved directly, to the end time
  context.write_summary(summary);
  const std::vector<double> no_porosity;
  FlowPicture picture{model->model().mesh(), model->state(), no_porosity, model->model().permeability(),
                      model->model().blocks()};
  picture.stop_requested = [&context] { return context.stop_requested(); };
  draw_figures(context.scenario, context.folder, picture);
  recorder.draw("");
  return summary;
}

}  // namespace hydrodda::run
