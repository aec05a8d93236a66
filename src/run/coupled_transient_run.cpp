// The coupled transient run: a CoupledModel stepped in time by the fixed-stress split, each
// step's passes its iterations (coupled_transient.hpp for the step control,
// coupled_transient_stepper.hpp for the steps). Recorded per step: history.csv, probes.csv and
// measure.csv; at t = 0 and each output time: fluid.pvd and blocks.pvd at their real times and
// checkpoint.bin, which an interrupt, --stop-after and the end write too; with bonds, the breaks
// of each step (fractures.csv's bond rows, history.csv's broken_bonds, bonds.pvd at the output
// times, figures/cracks.*); at the end summary.json and the figures (docs/coupling.md, "Coupled transient runs"). `run --resume`
// continues from the checkpoint bit for bit.

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "output/csv_table.hpp"
#include "output/plot_line.hpp"
#include "output/time_axis.hpp"
#include "run/bond_output.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_transient.hpp"
#include "run/coupled_transient_fractures.hpp"
#include "run/coupled_transient_stepper.hpp"
#include "run/figures.hpp"
#include "run/no_equilibrium.hpp"
#include "run/no_equilibrium_in_time.hpp"
#include "run/paraview_output.hpp"
#include "run/runs.hpp"
#include "run/transient_flow.hpp"
#include "scenario/load_times.hpp"

namespace hydrodda::run {

StepControl make_step_control(const scenario::Scenario& s) {
  const scenario::TransientDefinition& t = *s.flow->transient;
  return {t.time_step, t.max_time_step, t.time_step / std::pow(2.0, kMostCuts),
          std::max(3, s.coupling.max_iterations / 4)};
}

std::vector<double> find_step_stops(const scenario::Scenario& s) {
  const double end = s.flow->transient->end_time;
  std::vector<double> stops;
  for (const std::vector<double>& times : {s.flow->transient->output_times, scenario::find_load_times(s)})
    for (double t : times)
      if (t > 0.0 && t < end) stops.push_back(t);
  std::sort(stops.begin(), stops.end());
  stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
  stops.push_back(end);
  return stops;
}

double land_on_stop(double time, double step, double stop) {
  return time + step >= stop - 1e-6 * step ? stop - time : step;
}

double grow_step(const StepControl& control, double step, int passes) {
  return passes <= control.few_iterations ? std::min(step * kTimeStepGrowth, control.max_step) : step;
}

namespace {

using output::CsvTable;

// history.csv, probes.csv, measure.csv and fractures.csv, rows per step; the fields at output
// times; checkpoint.bin, whose record (output::CoupledTransientCheckpoint) holds all of it so
// far, the bonds broken so far in its DDA state.
class CoupledTransientRecorder {
 public:
  CoupledTransientRecorder(const RunContext& context, const CoupledModel& model)
      : context_(context), model_(model), fields_(context.folder, context.scenario.output.fields),
        sites_(locate_probes(context.scenario, model.mesh())), fractures_(context, model) {
    if (model.mechanics().bond_count() > 0) {
      fractures_.list_broken_bonds();
      bonds_.emplace(context.folder, context.scenario, model.mechanics(),
                     static_cast<int>(fracture_type_names(context.scenario).size()), BondClock::time_step);
    }
  }

  // A new run: the scenario's copy for resume, and the state at t = 0.
  void start() {
    record_.scenario_hash = output::hash_text(context_.scenario_text);
    record_.scenario_file = std::filesystem::absolute(context_.scenario.file).string();
    record_.input_files = hash_input_files(context_.scenario);
    record_.boundary_flows.assign(context_.scenario.flow->boundaries.size(), {});
    record_.probe_pressures.assign(sites_.size(), {});
    context_.folder.write("scenario.toml", context_.scenario_text);
    record({});
    write_fields();
  }
  // A continued run: what its checkpoint recorded, the series listed again, the fractures
  // measured again as the model stands (their rows up to its step kept).
  void resume_from(const output::CoupledTransientCheckpoint& saved) {
    record_ = saved;
    record_.mechanics = {};
    record_.coupling = {};
    fields_.list_written_at(record_.output_times);
    std::vector<FractureCounts> counts;
    for (std::size_t i = 0; i + 4 < record_.fracture_counts.size(); i += 5) {
      const double* c = &record_.fracture_counts[i];
      counts.push_back({static_cast<int>(c[0]), static_cast<int>(c[1]), c[2], c[3], c[4]});
    }
    fractures_.resume(record_.steps, record_.output_times, std::move(counts));
    if (bonds_) bonds_->continue_in_time(model_.mechanics(), broken_per_step(), record_.times, record_.output_times);
    hold(record_.steps, record_.time);  // the run went on from it: it held
  }
  void record(const StepRecord& r);
  void write_fields() {
    const double time = record_.times.back();
    const int written = static_cast<int>(record_.output_times.size());
    fields_.write_fluid(written, time, model_.mesh(), model_.loop().flow(), model_.loop().porosity().porosity,
                        model_.loop().permeability());
    fields_.write_blocks(written, time, model_.mechanics());
    fractures_.write_series(written, time);
    if (bonds_) bonds_->write_series(written, time, model_.mechanics());
    record_.output_times.push_back(time);
  }
  // checkpoint.bin of the state at the last step's end and where the steps stand; `ended`: the
  // run reached its end_time or failed at the floor.
  void save_checkpoint(const CoupledTransientStepper& stepper, bool ended) {
    const StepPosition& at = stepper.position();
    record_.ended = ended;
    record_.steps = at.steps;
    record_.time = at.time;
    record_.nominal_step = at.nominal;
    record_.next_stop = at.next_stop;
    const CoupledState& state = stepper.state_at_step_end();
    context_.folder.write("checkpoint.bin",
                          output::encode_coupled_transient_checkpoint(record_, state.mechanics, state.coupling));
  }
  void draw(const std::string& status) const;
  const std::optional<fractures::FractureState>& fracture_state() const { return fractures_.state(); }
  // The last state that held: the last time step after which no block was farther than its own
  // size (step 0: the blocks as built), the fractures open and the bonds broken by then.
  const HeldState& held_state() const { return held_; }

 private:
  void write_tables() const;
  std::vector<std::string> history_columns() const;
  // history.csv's broken_bonds of each step recorded so far (the row of t = 0 first).
  std::vector<int> broken_per_step() const;
  void hold(int step, double time);

  const RunContext& context_;
  const CoupledModel& model_;
  ParaviewOutput fields_;
  std::vector<ProbeSite> sites_;
  FracturesInTime fractures_;
  std::optional<BondOutput> bonds_;  // a model with bonds: its breaks, by the time step they broke in
  output::CoupledTransientCheckpoint record_;
  HeldState held_;
};

void CoupledTransientRecorder::hold(int step, double time) {
  const auto& state = fractures_.state();
  held_ = hold_time_step(step, time, model_.mechanics(), state ? &*state : nullptr);
}

std::vector<int> CoupledTransientRecorder::broken_per_step() const {
  std::vector<int> counts;
  for (const std::vector<std::string>& row : record_.history) {
    if (row.size() != history_columns().size())
      throw InputError("run --resume: the checkpoint's history has no broken_bonds column (written before coupled "
                       "transient runs recorded their breaks); run the scenario again");
    counts.push_back(std::stoi(row.back()));
  }
  return counts;
}

void CoupledTransientRecorder::record(const StepRecord& r) {
  const hydro::FlowSolution& flow = model_.loop().flow();
  const bool start = r.step == 0;
  std::vector<std::string> row{CsvTable::cell(static_cast<long long>(r.step)), CsvTable::cell(r.time),
                               start ? "" : CsvTable::cell(r.length),
                               start ? "" : CsvTable::cell(static_cast<long long>(r.passes)),
                               start ? "" : CsvTable::cell(static_cast<long long>(r.cuts)),
                               start ? "" : CsvTable::cell(r.last.head_change),
                               start ? "" : CsvTable::cell(r.last.displacement_change),
                               CsvTable::cell(flow.storage_rate), CsvTable::cell(flow.balance_error)};
  const std::vector<scenario::FlowBoundaryCondition>& boundaries = context_.scenario.flow->boundaries;
  for (std::size_t b = 0; b < boundaries.size(); ++b) {
    row.push_back(CsvTable::cell(flow.boundary_flow(boundaries[b].name)));
    record_.boundary_flows[b].push_back(flow.boundary_flow(boundaries[b].name));
  }
  record_.storage_rates.push_back(flow.storage_rate);
  // The bonds broken in the step's iterations, recorded at the step (before its fractures' rows,
  // as a coupled run's at the pass); only a step that converged gets here.
  const int broken = bonds_ ? bonds_->add_breaks(r.step, model_.mechanics(), fractures_.output(), r.time) : 0;
  fractures_.record(r.step, r.time);
  if (find_escaping_blocks(model_.mechanics()).empty()) hold(r.step, r.time);
  if (fractures_.measured()) {
    const FractureCounts& c = fractures_.counts().back();
    for (std::string& cell : fracture_count_cells(c)) row.push_back(std::move(cell));
    record_.fracture_counts.insert(record_.fracture_counts.end(),
                                   {static_cast<double>(c.open), static_cast<double>(c.partly_open), c.open_length,
                                    c.largest_opening, c.largest_hydraulic});
  }
  if (bonds_) row.push_back(CsvTable::cell(static_cast<long long>(broken)));
  record_.history.push_back(std::move(row));
  record_.times.push_back(r.time);
  for (std::size_t p = 0; p < sites_.size(); ++p) {
    const double head = value_at(sites_[p], model_.mesh(), flow.head);
    const double pressure = value_at(sites_[p], model_.mesh(), flow.pressure);
    record_.probes.push_back({CsvTable::cell(r.time), sites_[p].name, CsvTable::cell(head), CsvTable::cell(pressure)});
    record_.probe_pressures[p].push_back(pressure);
  }
  const std::vector<scenario::MeasurePoint>& measures = context_.scenario.mechanics->measures;
  const std::vector<geometry::Point> positions = model_.mechanics().measured_positions();
  for (std::size_t i = 0; i < measures.size(); ++i)
    record_.measure.push_back({CsvTable::cell(static_cast<long long>(r.step)), CsvTable::cell(r.time), measures[i].name,
                               CsvTable::cell(positions[i].x), CsvTable::cell(positions[i].y),
                               CsvTable::cell(positions[i].x - measures[i].point.x),
                               CsvTable::cell(positions[i].y - measures[i].point.y)});
  write_tables();
}

std::vector<std::string> CoupledTransientRecorder::history_columns() const {
  std::vector<std::string> columns{"step", "time", "time_step", "iterations", "cuts", "head_change",
                                   "displacement_change", "storage_rate", "balance"};
  for (const scenario::FlowBoundaryCondition& bc : context_.scenario.flow->boundaries) columns.push_back("flow_" + bc.name);
  if (fractures_.measured())
    for (const std::string& c : fracture_count_columns()) columns.push_back(c);
  if (bonds_) columns.push_back("broken_bonds");
  return columns;
}

void CoupledTransientRecorder::write_tables() const {
  const std::vector<std::string> columns = history_columns();
  const auto write = [this](const char* name, std::vector<std::string> header,
                            const std::vector<std::vector<std::string>>& rows) {
    CsvTable table(std::move(header));
    for (const std::vector<std::string>& row : rows) table.add_row(row);
    context_.folder.write(name, table.text());
  };
  write("history.csv", columns, record_.history);
  if (!sites_.empty()) write("probes.csv", {"time", "name", "head", "pressure"}, record_.probes);
  if (!context_.scenario.mechanics->measures.empty())
    write("measure.csv", {"step", "time", "name", "x", "y", "ux", "uy"}, record_.measure);
}

// Against time (log time when the run starts with steps much shorter than it): probes.* (each
// probe's pressure), flows.* (each boundary's outward flow and the rate of storage) and, with
// fractures, fractures.* (how many are open); apertures.* and the fields of the state reached.
void CoupledTransientRecorder::draw(const std::string& status) const {
  const scenario::Scenario& s = context_.scenario;
  if (s.output.figures.empty()) return;
  const coupling::StaggeredLoop& loop = model_.loop();
  FlowPicture picture{model_.mesh(), loop.flow(), loop.porosity().porosity, loop.permeability(),
                      model_.block_polygons(), status, loop.iterations()};
  picture.stop_requested = [this] { return context_.stop_requested(); };
  draw_figures(s, context_.folder, picture);
  if (const auto& state = fractures_.state())
    draw_aperture_figure(s, context_.folder, model_.block_polygons(), *state,
                         {fmt::format("t = {:g} s", record_.times.back()), status});
  if (bonds_)
    bonds_->draw_figure(s, model_.mechanics(), fmt::format("t = {:g} s", record_.times.back()) +
                                                   (status.empty() ? "" : ", " + status));
  if (record_.times.size() < 2) return;
  const bool log_time = s.flow->transient->time_step <= 0.01 * s.flow->transient->end_time;
  // The t = 0 row is left off a log axis.
  const auto from_first = [log_time](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + (log_time ? 1 : 0), v.end());
  };
  const std::vector<double> times = from_first(record_.times);
  const auto render = [&](output::LinePlotSpec plot, const std::string& name) {
    plot.title = s.title;
    plot.warning = status;
    output::put_time_axis(plot);  // the times in seconds, shown in the unit of their span
    plot.x_log = log_time;
    for (const std::string& format : s.output.figures)
      output::render_line_plot(context_.folder.figures() / (name + "." + format), plot);
  };
  if (!sites_.empty()) {
    output::LinePlotSpec probes;
    probes.y_label = "pressure (Pa)";
    for (std::size_t p = 0; p < sites_.size(); ++p)
      probes.series.push_back({sites_[p].name, times, from_first(record_.probe_pressures[p]), {}});
    render(probes, "probes");
  }
  output::LinePlotSpec flows;
  flows.y_label = "flow (m²/s per m)";
  for (std::size_t b = 0; b < record_.boundary_flows.size(); ++b)
    flows.series.push_back({"out by " + s.flow->boundaries[b].name, times, from_first(record_.boundary_flows[b]), {}});
  flows.series.push_back({"into storage", times, from_first(record_.storage_rates), {}});
  render(flows, "flows");
  if (fractures_.measured()) {
    const std::vector<FractureCounts>& counts = fractures_.counts();
    render(plot_open_fractures(times, std::vector<FractureCounts>(counts.begin() + (log_time ? 1 : 0), counts.end())),
           "fractures");
  }
}

output::RunSummary summarise(const CoupledModel& model, double time, int steps, std::chrono::steady_clock::time_point start) {
  output::RunSummary summary = summarise_coupled_transient(model, time, steps);
  summary.timings = model.timings();
  summary.timings.push_back({"transient", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
  return summary;
}

void report_step(const RunContext& context, const StepRecord& r) {
  ProgressReport report;
  report.kind = ProgressReport::Kind::coupling_pass;
  report.count = r.step;
  report.time = r.time;
  report.head_change = r.last.head_change;
  report.displacement_change = r.last.displacement_change;
  report.message = fmt::format("step {}: t = {:g} s in {} iterations{}", r.step, r.time, r.passes,
                               r.cuts > 0 ? fmt::format(" after {} cut(s)", r.cuts) : "");
  context.report(report);
}

// A step cut to the floor whose last try threw blocks farther than their own size in its first
// iteration: no equilibrium under the loads at its end (docs/output.md, "A run that found no
// equilibrium"). The run folder
// holds the last step that converged (`summary`'s); the message names the step, its load then,
// the blocks where its last try left them and the last state that held.
RunFailure end_without_equilibrium(const RunContext& context, const CoupledModel& model,
                                   const CoupledTransientStepper& stepper, const CoupledTransientRecorder& recorder,
                                   output::RunSummary summary) {
  std::string message = describe_time_step_without_equilibrium(context.scenario, stepper, recorder.held_state(),
                                                              model.mechanics(), &context.folder);
  summary.last_held = summarise_held_state(recorder.held_state());
  try {
    recorder.draw(describe_status_for_figures(fmt::format("no equilibrium after t = {:g} s", stepper.time()), message));
  } catch (const std::exception& e) {
    spdlog::warn("the figures of the run without equilibrium could not be drawn: {}", e.what());
  }
  return RunFailure(RunStatus::no_equilibrium, std::move(message), std::move(summary));
}

// The model of a run, or of a run continued from its checkpoint at the step it saved.
std::unique_ptr<CoupledModel> build_model(const RunContext& context) {
  auto model = std::make_unique<CoupledModel>(context.scenario, context.mesh_cache);
  model->set_stop_request(context.callbacks.stop_requested);
  model->start_in_time();
  if (const output::CoupledTransientCheckpoint* saved = context.resume_coupled_transient)
    model->import_state({saved->mechanics, saved->coupling});
  return model;
}

}  // namespace

output::RunSummary summarise_coupled_transient(const CoupledModel& model, double time, int steps) {
  output::RunSummary summary = model.summary();
  summary.time = time;
  summary.iterations = steps;
  if (summary.flow) summary.flow->storage_rate = model.loop().flow().storage_rate;
  return summary;
}

output::RunSummary run_coupled_transient(const RunContext& context) {
  const scenario::Scenario& s = context.scenario;
  const output::CoupledTransientCheckpoint* resume = context.resume_coupled_transient;
  if (context.resume)
    throw InputError("run --resume: the checkpoint is a steady coupled run's, the scenario has [flow.transient]");
  std::optional<UnstoppableStage> building(context.callbacks);
  const std::unique_ptr<CoupledModel> model = build_model(context);
  const std::optional<fractures::FractureState> no_fractures;
  const TellModelAtEnd tell_model_at_end(context.callbacks, *model, no_fractures);
  const auto start = std::chrono::steady_clock::now();
  CoupledTransientRecorder recorder(context, *model);
  CoupledTransientStepper stepper(*model);
  if (resume) {
    stepper.resume_at({resume->steps, resume->time, resume->nominal_step, resume->next_stop});
    recorder.resume_from(*resume);
  } else {
    recorder.start();
    recorder.save_checkpoint(stepper, false);
  }
  building.reset();

  const std::vector<double>& outputs = s.flow->transient->output_times;
  while (!stepper.finished()) {
    if (context.stop_after && stepper.steps() >= *context.stop_after) {
      recorder.save_checkpoint(stepper, false);
      output::RunSummary summary = summarise(*model, stepper.time(), stepper.steps(), start);
      summary.status = "stopped";
      summary.message = fmt::format("stopped after time step {} at t = {:g} s (--stop-after)", stepper.steps(),
                                    stepper.time());
      return summary;
    }
    const CoupledTransientStepper::Outcome outcome = stepper.step([&context] { return context.stop_requested(); });
    if (outcome == CoupledTransientStepper::Outcome::interrupted) {
      recorder.save_checkpoint(stepper, false);  // the last finished step's state, to resume from
      throw RunFailure(RunStatus::interrupted,
                       fmt::format("interrupted at t = {:g} s, after {} steps", stepper.time(), stepper.steps()),
                       summarise(*model, stepper.time(), stepper.steps(), start));
    }
    if (outcome == CoupledTransientStepper::Outcome::failed) break;
    const StepRecord& r = stepper.record();
    recorder.record(r);
    const bool output_time = r.time >= stepper.end_time() || std::find(outputs.begin(), outputs.end(), r.time) != outputs.end();
    if (output_time) {
      recorder.write_fields();
      recorder.save_checkpoint(stepper, stepper.finished());
    }
    report_step(context, r);
  }
  output::RunSummary summary = summarise(*model, stepper.time(), stepper.steps(), start);
  if (const auto& state = recorder.fracture_state())
    summary.fractures = summarise_fractures(*state, fracture_type_names(s));
  summary.converged = !stepper.failed();
  if (failed_without_equilibrium(stepper)) {
    recorder.write_fields();
    recorder.save_checkpoint(stepper, true);
    throw end_without_equilibrium(context, *model, stepper, recorder, std::move(summary));
  }
  if (stepper.failed()) {
    summary.message = stepper.failure();
    spdlog::warn("{}", stepper.failure());
    recorder.write_fields();
    recorder.save_checkpoint(stepper, true);
  }
  context.write_summary(summary);
  recorder.draw(stepper.failed() ? describe_status_for_figures(fmt::format("not converged at t = {:g} s", stepper.time()), "")
                                 : "");
  return summary;
}

}  // namespace hydrodda::run
