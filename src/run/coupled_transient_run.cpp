// The coupled transient run: a CoupledModel stepped in time by the fixed-stress split, each
// step's passes its iterations (coupled_transient.hpp for the step control). Recorded per step:
// history.csv, probes.csv and measure.csv; at t = 0 and each output time: fluid.pvd and
// blocks.pvd at their real times; at the end summary.json and the figures
// (docs/coupling.md, "Coupled transient runs").

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "output/csv_table.hpp"
#include "output/plot_line.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_transient.hpp"
#include "run/coupled_transient_fractures.hpp"
#include "run/figures.hpp"
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

// Counts a step's passes and keeps its last; stops at the run's stop request.
class StepObserver final : public coupling::PassObserver {
 public:
  explicit StepObserver(const RunContext& context) : context_(context) {}
  bool stop_requested() override { return context_.stop_requested(); }
  void after_pass(const coupling::PassReport& report) override {
    ++passes;
    last = report;
  }
  int passes = 0;
  coupling::PassReport last;

 private:
  const RunContext& context_;
};

// What one step did: its end, the passes it took, the cuts before it converged.
struct StepRecord {
  int step = 0;
  double time = 0.0, length = 0.0;
  int passes = 0, cuts = 0;
  coupling::PassReport last;
};

// history.csv, probes.csv, measure.csv and fractures.csv, rows per step; the fields at output
// times.
class CoupledTransientRecorder {
 public:
  CoupledTransientRecorder(const RunContext& context, const CoupledModel& model)
      : context_(context), model_(model), fields_(context.folder, context.scenario.output.fields),
        sites_(locate_probes(context.scenario, model.mesh())), fractures_(context, model) {
    std::vector<std::string> columns{"step", "time", "time_step", "iterations", "cuts", "head_change",
                                     "displacement_change", "storage_rate", "balance"};
    for (const scenario::FlowBoundaryCondition& bc : context.scenario.flow->boundaries) columns.push_back("flow_" + bc.name);
    if (fractures_.measured())
      for (const std::string& c : fracture_count_columns()) columns.push_back(c);
    history_.emplace(columns);
    probe_pressures_.assign(sites_.size(), {});
  }
  void record(const StepRecord& r);
  void write_fields() {
    fields_.write_fluid(written_, times_.back(), model_.mesh(), model_.loop().flow(), model_.loop().porosity().porosity,
                        model_.loop().permeability());
    fields_.write_blocks(written_, times_.back(), model_.mechanics());
    fractures_.write_series(written_, times_.back());
    ++written_;
  }
  void draw(const std::string& status) const;
  const std::optional<fractures::FractureState>& fracture_state() const { return fractures_.state(); }

 private:
  const RunContext& context_;
  const CoupledModel& model_;
  ParaviewOutput fields_;
  std::vector<ProbeSite> sites_;
  std::optional<CsvTable> history_;
  CsvTable probes_{{"time", "name", "head", "pressure"}};
  CsvTable measure_{{"step", "time", "name", "x", "y", "ux", "uy"}};
  std::vector<double> times_;
  std::vector<std::vector<double>> probe_pressures_;
  std::vector<std::vector<double>> boundary_flows_;  // per boundary, per step
  std::vector<double> storage_rates_;
  FracturesInTime fractures_;
  int written_ = 0;
};

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
  boundary_flows_.resize(boundaries.size());
  for (std::size_t b = 0; b < boundaries.size(); ++b) {
    row.push_back(CsvTable::cell(flow.boundary_flow(boundaries[b].name)));
    boundary_flows_[b].push_back(flow.boundary_flow(boundaries[b].name));
  }
  storage_rates_.push_back(flow.storage_rate);
  fractures_.record(r.step, r.time);
  if (fractures_.measured())
    for (std::string& cell : fracture_count_cells(fractures_.counts().back())) row.push_back(std::move(cell));
  history_->add_row(row);
  context_.folder.write("history.csv", history_->text());
  times_.push_back(r.time);
  for (std::size_t p = 0; p < sites_.size(); ++p) {
    const double head = value_at(sites_[p], model_.mesh(), flow.head);
    const double pressure = value_at(sites_[p], model_.mesh(), flow.pressure);
    probes_.add_row({CsvTable::cell(r.time), sites_[p].name, CsvTable::cell(head), CsvTable::cell(pressure)});
    probe_pressures_[p].push_back(pressure);
  }
  if (!sites_.empty()) context_.folder.write("probes.csv", probes_.text());
  const std::vector<scenario::MeasurePoint>& measures = context_.scenario.mechanics->measures;
  const std::vector<geometry::Point> positions = model_.mechanics().measured_positions();
  for (std::size_t i = 0; i < measures.size(); ++i)
    measure_.add_row({CsvTable::cell(static_cast<long long>(r.step)), CsvTable::cell(r.time), measures[i].name,
                      CsvTable::cell(positions[i].x), CsvTable::cell(positions[i].y),
                      CsvTable::cell(positions[i].x - measures[i].point.x),
                      CsvTable::cell(positions[i].y - measures[i].point.y)});
  if (!measures.empty()) context_.folder.write("measure.csv", measure_.text());
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
                         {fmt::format("t = {:g} s", times_.back()), status});
  if (times_.size() < 2) return;
  const bool log_time = s.flow->transient->time_step <= 0.01 * s.flow->transient->end_time;
  // The t = 0 row is left off a log axis.
  const auto from_first = [log_time](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + (log_time ? 1 : 0), v.end());
  };
  const std::vector<double> times = from_first(times_);
  const auto render = [&](output::LinePlotSpec plot, const std::string& name) {
    plot.title = s.title;
    plot.warning = status;
    plot.x_label = "time (s)";
    plot.x_log = log_time;
    for (const std::string& format : s.output.figures)
      output::render_line_plot(context_.folder.figures() / (name + "." + format), plot);
  };
  if (!sites_.empty()) {
    output::LinePlotSpec probes;
    probes.y_label = "pressure (Pa)";
    for (std::size_t p = 0; p < sites_.size(); ++p)
      probes.series.push_back({sites_[p].name, times, from_first(probe_pressures_[p]), {}});
    render(probes, "probes");
  }
  output::LinePlotSpec flows;
  flows.y_label = "flow (m²/s per m)";
  for (std::size_t b = 0; b < boundary_flows_.size(); ++b)
    flows.series.push_back({"out by " + s.flow->boundaries[b].name, times, from_first(boundary_flows_[b]), {}});
  flows.series.push_back({"into storage", times, from_first(storage_rates_), {}});
  render(flows, "flows");
  if (fractures_.measured()) {
    const std::vector<FractureCounts>& counts = fractures_.counts();
    render(plot_open_fractures(times, std::vector<FractureCounts>(counts.begin() + (log_time ? 1 : 0), counts.end())),
           "fractures");
  }
}

// How one attempt at a step ended: converged, or why not.
struct Attempt {
  bool converged = false;
  bool interrupted = false;
  std::string why;
};

Attempt try_step(const RunContext& context, CoupledModel& model, StepObserver& observer, double time, double length) {
  const scenario::Scenario& s = context.scenario;
  model.begin_time_step(time, length);
  coupling::LoopResult result;
  try {
    result = model.run({model.iterations() + s.coupling.max_iterations, std::nullopt}, observer);
  } catch (const coupling::PassInterrupted&) {
    return {false, true, ""};
  } catch (const std::exception& e) {
    model.abandon_pass();
    return {false, false, e.what()};
  }
  switch (result.end) {
    case coupling::LoopEnd::converged: return {true, false, ""};
    case coupling::LoopEnd::stop_requested: return {false, true, ""};
    case coupling::LoopEnd::diverging: return {false, false, "its iterations diverged"};
    case coupling::LoopEnd::escaping: return {false, false, "blocks escaped beyond their own size"};
    default: {
      const coupling::PassReport& r = observer.last;
      return {false, false,
              fmt::format("its iterations did not converge in {} (coupling.max_iterations; head change {:.3e}, "
                          "displacement change {:.3e}, tolerance {:g})",
                          s.coupling.max_iterations, r.head_change, r.displacement_change, s.coupling.tolerance)};
    }
  }
}

output::RunSummary summarise(const CoupledModel& model, double time, int steps, std::chrono::steady_clock::time_point start) {
  output::RunSummary summary = model.summary();
  summary.time = time;
  summary.iterations = steps;
  if (summary.flow) summary.flow->storage_rate = model.loop().flow().storage_rate;
  summary.timings = model.timings();
  summary.timings.push_back({"transient", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
  return summary;
}

}  // namespace

output::RunSummary run_coupled_transient(const RunContext& context) {
  const scenario::Scenario& s = context.scenario;
  if (context.resume)
    throw InputError("run --resume of a coupled transient run ([mechanics] with [flow.transient]) is not built yet");
  std::optional<UnstoppableStage> building(context.callbacks);
  CoupledModel model(s, context.mesh_cache);
  model.set_stop_request(context.callbacks.stop_requested);
  model.start_in_time();
  const std::optional<fractures::FractureState> no_fractures;
  const TellModelAtEnd tell_model_at_end(context.callbacks, model, no_fractures);
  const auto start = std::chrono::steady_clock::now();
  context.folder.write("scenario.toml", context.scenario_text);
  CoupledTransientRecorder recorder(context, model);
  recorder.record({});
  recorder.write_fields();
  building.reset();

  const StepControl control = make_step_control(s);
  const std::vector<double> stops = find_step_stops(s);
  const std::vector<double>& outputs = s.flow->transient->output_times;
  std::size_t next_stop = 0;
  double time = 0.0, nominal = control.first_step;
  int steps = 0;
  CoupledState saved = model.export_state();
  std::string failure;
  while (time < s.flow->transient->end_time) {
    StepObserver observer(context);
    int cuts = 0;
    double length = land_on_stop(time, nominal, stops[next_stop]);
    Attempt attempt;
    for (;;) {
      attempt = try_step(context, model, observer, time, length);
      if (attempt.converged || attempt.interrupted) break;
      model.import_state(saved);  // back to the last step's end
      if (length / 2.0 < control.floor) break;
      spdlog::info("t = {:g} s: the step of {:g} s failed ({}); cut to {:g} s", time, length, attempt.why, length / 2);
      length /= 2.0;
      ++cuts;
    }
    if (attempt.interrupted) {
      model.import_state(saved);
      throw RunFailure(RunStatus::interrupted, fmt::format("interrupted at t = {:g} s, after {} steps", time, steps),
                       summarise(model, time, steps, start));
    }
    if (!attempt.converged) {
      failure = fmt::format("not converged at t = {:g} s: the step from there failed at {:g} s after {} cut(s), and "
                            "half of it would be under the floor of {:g} s (flow.transient.time_step / 2^{}); the "
                            "last try: {}",
                            time, length, cuts, control.floor, kMostCuts, attempt.why);
      break;
    }
    const bool landed = length == stops[next_stop] - time;
    time = landed ? stops[next_stop] : time + length;
    if (landed) ++next_stop;
    ++steps;
    saved = model.export_state();
    recorder.record({steps, time, length, observer.passes, cuts, observer.last});
    const bool output_time = time >= s.flow->transient->end_time || std::find(outputs.begin(), outputs.end(), time) != outputs.end();
    if (output_time) recorder.write_fields();
    // A cut step's length is where the next starts from; a full one grows when it came easily.
    nominal = cuts > 0 ? length : (landed && length < nominal ? nominal : grow_step(control, length, observer.passes));
    ProgressReport report;
    report.kind = ProgressReport::Kind::coupling_pass;
    report.count = steps;
    report.time = time;
    report.head_change = observer.last.head_change;
    report.displacement_change = observer.last.displacement_change;
    report.message = fmt::format("step {}: t = {:g} s in {} iterations{}", steps, time, observer.passes,
                                 cuts > 0 ? fmt::format(" after {} cut(s)", cuts) : "");
    context.report(report);
  }
  output::RunSummary summary = summarise(model, time, steps, start);
  if (const auto& state = recorder.fracture_state())
    summary.fractures = summarise_fractures(*state, fracture_type_names(s));
  summary.converged = failure.empty();
  if (!failure.empty()) {
    summary.message = failure;
    spdlog::warn("{}", failure);
    recorder.write_fields();
  }
  context.write_summary(summary);
  recorder.draw(failure.empty() ? "" : describe_status_for_figures(fmt::format("not converged at t = {:g} s", time), ""));
  return summary;
}

}  // namespace hydrodda::run
