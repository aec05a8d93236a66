
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <optional>

#include "run/bond_output.hpp"
#include "run/figures.hpp"
#include "run/fracture_output.hpp"
#include "run/load_stall.hpp"
#include "run/model_building.hpp"
#include "run/no_equilibrium.hpp"
#include "run/mechanics_model.hpp"
#include "run/mechanics_rest.hpp"
#include "run/paraview_output.hpp"
#include "run/reactions.hpp"
#include "run/run_summary.hpp"
#include "run/runs.hpp"
#include "run/scenario_fractures.hpp"
#include "output/csv_table.hpp"

namespace hydrodda::run {

namespace {

using output::CsvTable;
using geometry::Point;

// A static run's last state that held: the last step after which no block was farther than
// its own size. Its blocks and contacts are kept (where the scenario has traces to measure) so
// that its fractures are measured only if the run ends without equilibrium.
class HeldStep {
 public:
  HeldStep(const std::optional<fractures::FractureMeter>& meter, const dda::System& system)
      : meter_(meter), bonded_(system.bond_count() > 0) {
    keep(0, system);
  }

  // After each finished step: kept when no block is beyond its size.
  void update(long long step, const dda::System& system) {
    if (find_escaping_blocks(system).empty()) keep(step, system);
  }

  HeldState state(const coupling::JointApertureLaws& laws) const {
    HeldState held;
    held.step = step_;
    if (step_ > 0) held.name = fmt::format("DDA step {}", step_);
    if (bonded_) held.broken_bonds = broken_bonds_;
    if (measures()) take_open_fractures(meter_->measure(polygons_, tolerance_, contacts_, laws), held);
    return held;
  }

 private:
  const std::optional<fractures::FractureMeter>& meter_;
  bool bonded_;
  long long step_ = 0;
  int broken_bonds_ = 0;
  std::vector<geometry::Polygon> polygons_;
  std::vector<dda::ContactInfo> contacts_;
  double tolerance_ = 0.0;

  bool measures() const { return meter_ && !meter_->layout().traces.empty(); }
  void keep(long long step, const dda::System& system) {
    step_ = step;
    broken_bonds_ = static_cast<int>(system.bond_breaks().size());
    if (!measures()) return;
    polygons_.clear();
    for (int b = 0; b < system.block_count(); ++b) polygons_.push_back(system.polygon(b));
    contacts_ = system.contacts();
    tolerance_ = system.penetration_tolerance();
  }
};

}  // namespace

output::RunSummary run_mechanics(const RunContext& context) {
  const scenario::Scenario& s = context.scenario;
  const scenario::MechanicsDefinition& m = *s.mechanics;
  const auto start = std::chrono::steady_clock::now();

  std::optional<UnstoppableStage> building(context.callbacks);
  MechanicsModel model(s);
  building.reset();
  const dda::System& system = model.system();
  // A step on a large model may take minutes: it is left between its passes when asked to stop.
  model.set_interrupt_check([&context] { return context.stop_requested(); });

  // Each prescribed displacement's reaction, then, in a model with bonds, the bonds broken in
  // each step and in all (added last).
  const bool bonded = system.bond_count() > 0;
  std::vector<std::string> history_columns{"step", "time", "time_step", "open_close_iterations", "contacts",
                                           "max_displacement", "max_penetration"};
  const std::vector<std::string> reactions = reaction_columns(m.displacements);
  history_columns.insert(history_columns.end(), reactions.begin(), reactions.end());
  if (bonded) history_columns.insert(history_columns.end(), {"broken_bonds", "broken_bonds_total"});
  CsvTable history(history_columns);
  CsvTable measure({"step", "time", "name", "x", "y", "ux", "uy"});
  const auto write_tables = [&] {
    context.folder.write("history.csv", history.text());
    if (!m.measures.empty()) context.folder.write("measure.csv", measure.text());
  };

  ParaviewOutput paraview(context.folder, s.output.fields);
  const std::optional<fractures::FractureMeter> meter = make_fracture_meter(s);
  const coupling::JointApertureLaws joint_laws =
      meter ? make_joint_aperture_laws(s, meter->layout().traces) : coupling::JointApertureLaws{};
  const std::vector<std::string> fracture_types = fracture_type_names(s);
  FractureOutput fractures(context.folder, /*with_flow=*/false, fracture_types);
  std::optional<BondOutput> bonds;
  if (bonded) {
    fractures.list_broken_bonds();
    bonds.emplace(context.folder, s, system, static_cast<int>(fracture_types.size()));
  }
  std::optional<fractures::FractureState> fracture_state;  // of the blocks as they are, when measured at this step
  // The blocks and fractures of the last output step: what the figure of a run that stops shows.
  struct OutputState {
    long long step = 0;
    std::vector<geometry::Polygon> polygons;
    fractures::FractureState fractures;
  };
  std::optional<OutputState> last_output;
  const TellModelAtEnd tell_model_at_end(context.callbacks, model, fracture_state);
  // Blocks and contacts, and the fractures' rows and lines, at an output step.
  const auto write_step = [&](long long step, double time) {
    paraview.write_blocks(static_cast<int>(step), time, system);
    if (bonds) bonds->write_series(static_cast<int>(step), time, system);
    if (!meter) return;
    OutputState& out = last_output.emplace();
    out.step = step;
    for (int b = 0; b < system.block_count(); ++b) out.polygons.push_back(system.polygon(b));
    out.fractures = meter->measure(out.polygons, system.penetration_tolerance(), system.contacts(), joint_laws);
    fracture_state = out.fractures;
    fractures.add_rows(step, time, out.fractures);
    if (s.output.fields.fractures) fractures.write_series(static_cast<int>(step), time, out.fractures);
  };
  const auto draw_figure = [&](const std::string& status) {
    if (bonds) bonds->draw_figure(s, system, fmt::format("DDA step {}{}", model.steps(), status.empty() ? "" : ", " + status));
    if (last_output)
      draw_aperture_figure(s, context.folder, last_output->polygons, last_output->fractures,
                           {fmt::format("DDA step {}", last_output->step), status});
  };
  // A run that stops before its end: its figure of the last output step says how it stopped.
  const auto stop = [&](RunStatus status, std::string message, const std::string& figure_status,
                        std::optional<output::LastHeldSummary> last_held = std::nullopt) {
    write_tables();
    try {
      draw_figure(figure_status);
    } catch (const std::exception& e) {
      spdlog::warn("the figure of the stopped run could not be drawn: {}", e.what());
    }
    output::RunSummary summary = model.summary();
    summary.last_held = std::move(last_held);
    return RunFailure(status, std::move(message), std::move(summary));
  };
  HeldStep held_step(meter, system);
  // A static analysis whose blocks went farther than their own size and still move has found no
  // equilibrium under its load: named as such, with the blocks of the last finished step and
  // the fractures and bonds of the last that held.
  const auto no_equilibrium = [&](const std::vector<coupling::EscapingBlock>& escaping) {
    HeldState held = held_step.state(joint_laws);
    if (held.broken_bonds) held.broken_bonds_later = static_cast<int>(system.bond_breaks().size()) - *held.broken_bonds;
    std::vector<geometry::Polygon> polygons;
    for (int b = 0; b < system.block_count(); ++b) polygons.push_back(system.polygon(b));
    const std::string message = describe_no_equilibrium(s, locate_escaping_blocks(escaping, polygons), held,
                                                        fmt::format("DDA step {}", model.steps()), &context.folder);
    return stop(RunStatus::no_equilibrium, message,
                describe_status_for_figures(fmt::format("no equilibrium at step {}", model.steps()), message),
                summarise_held_state(held));
  };
  const bool static_analysis = m.analysis == dda::Analysis::static_;
  dda::StepReport last_step;
  write_step(0, 0.0);
  long long last_written = 0;
  LoadStallWatch stall_watch(m);
  StallBreaks stall_breaks;
  // A static run that cannot raise its load further (load_stall.hpp): ended at the last load it
  // held, with no equilibrium.
  const auto load_stalled = [&](long long step, double time) {
    if (last_written != step) write_step(step, time);
    const std::string message = describe_load_stall(s, stall_watch.stall(), time,
                                                    describe_reactions(m.displacements, system), stall_breaks);
    return stop(RunStatus::no_equilibrium, message,
                describe_status_for_figures(fmt::format("load stalled at t = {:g} s", time), message),
                summarise_held_state(held_step.state(joint_laws)));
  };
  // Or past it, where the stall's tries broke bonds still whole: they break at the state held.
  const auto break_at_stall = [&](double time) {
    const int broke = model.break_bonds_of_last_cut_try();
    if (broke == 0) return false;
    if (stall_breaks.bonds == 0) stall_breaks.first = time;
    stall_breaks.bonds += broke;
    stall_watch.restart();
    spdlog::info("t = {:g} s: the load stalled, and the {} its last breaking try broke {} at the state held", time,
                 broke == 1 ? "bond" : fmt::format("{} bonds", broke), broke == 1 ? "breaks" : "break");
    return true;
  };
  try {
    while (!model.finished()) {
      if (context.stop_requested())
        throw stop(RunStatus::interrupted,
                   fmt::format("interrupted at step {} (t = {:g} s)", model.steps(), system.time()),
                   fmt::format("interrupted at step {}", model.steps()));
      bool stalled = false;  // and no bond left to break: the run ends
      const dda::StepReport r = model.step([&](const dda::StepReport& each) {
        stalled = static_analysis && stall_watch.update(each) && !break_at_stall(each.time);
        return stalled;
      });
      last_step = r;
      if (m.analysis == dda::Analysis::static_) held_step.update(model.steps(), system);
      fracture_state.reset();  // no longer the blocks' state: measured again at an output step
      const long long step = model.steps();
      std::vector<std::string> row{CsvTable::cell(step), CsvTable::cell(r.time), CsvTable::cell(r.time_step),
                                   CsvTable::cell(static_cast<long long>(r.open_close_iterations)),
                                   CsvTable::cell(static_cast<long long>(r.contacts)), CsvTable::cell(r.max_displacement),
                                   CsvTable::cell(r.max_penetration)};
      for (const Point reaction : sum_reactions(system, m.displacements.size())) {
        row.push_back(CsvTable::cell(reaction.x));
        row.push_back(CsvTable::cell(reaction.y));
      }
      if (bonds) {
        const int broken = bonds->add_breaks(step, system, fractures);
        row.push_back(CsvTable::cell(static_cast<long long>(broken)));
        row.push_back(CsvTable::cell(static_cast<long long>(system.bond_breaks().size())));
      }
      history.add_row(row);
      const auto positions = system.measured_positions();
      for (std::size_t i = 0; i < positions.size(); ++i) {
        const Point p0 = m.measures[i].point;
        measure.add_row({CsvTable::cell(step), CsvTable::cell(r.time), m.measures[i].name,
                         CsvTable::cell(positions[i].x), CsvTable::cell(positions[i].y),
                         CsvTable::cell(positions[i].x - p0.x), CsvTable::cell(positions[i].y - p0.y)});
      }
      if (step % 100 == 0) write_tables();
      if (step % s.output.every == 0) {
        write_step(step, r.time);
        last_written = step;
      }
      if (stalled) throw load_stalled(step, r.time);
      ProgressReport report;
      report.kind = ProgressReport::Kind::mechanics_step;
      report.count = step;
      report.time = r.time;
      report.contacts = r.contacts;
      report.max_displacement = r.max_displacement;
      report.message = fmt::format("step {} t = {:.4g} s, {} contacts, max step displacement {:.3g} m", step,
                                   r.time, r.contacts, r.max_displacement);
      context.report(report);
    }
  } catch (const RunFailure&) {
    throw;
  } catch (const dda::StepInterrupted& e) {
    // The system is as the last finished step left it, which the tables and summary describe.
    throw stop(RunStatus::interrupted,
               fmt::format("interrupted at step {} (t = {:g} s), {}", model.steps(), system.time(), e.what()),
               fmt::format("interrupted at step {}", model.steps()));
  } catch (const std::exception& e) {
    // The fractures were measured at an earlier output step, not at the state the run failed
    // in: a front end is told of none, as summary.json gives none.
    fracture_state.reset();
    const long long failed = model.steps() + 1;
    // A step that fails while blocks fly off is the breach, not the step (cut to nothing).
    if (const auto escaping = find_escaping_blocks(system); static_analysis && !escaping.empty()) {
      spdlog::debug("mechanics failed at step {} as blocks escaped: {}", failed, e.what());
      throw no_equilibrium(escaping);
    }
    throw stop(RunStatus::failed,
               fmt::format("mechanics failed at step {} (t = {:g} s): {}", failed, system.time(), e.what()),
               describe_status_for_figures(fmt::format("failed at step {}", failed), e.what()));
  }
  write_tables();
  if (last_written != model.steps()) write_step(model.steps(), system.time());
  // Still moving at the end (its last step moved a vertex past the contacts' own precision).
  if (const auto escaping = find_escaping_blocks(system);
      static_analysis && !escaping.empty() && last_step.max_displacement > system.penetration_tolerance())
    throw no_equilibrium(escaping);
  if (const std::string unreached = describe_unreached_displacement(s, system); !unreached.empty())
    throw stop(RunStatus::failed, unreached, describe_status_for_figures("failed", unreached));

  output::RunSummary summary = model.summary();
  if (fracture_state) summary.fractures = summarise_fractures(*fracture_state, fracture_types);
  // Mechanics alone has no coupling loop: a static run has converged when its blocks are at rest
  // at its end, a dynamic one when it reached its end.
  const std::string moving =
      static_analysis ? describe_motion_at_end(s, system, last_step, model.steps()) : std::string();
  summary.converged = moving.empty();
  if (!moving.empty()) {
    summary.message = moving;
    spdlog::warn("{}", moving);
  }
  summary.timings.push_back(
      {"mechanics", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
  context.write_summary(summary);  // the run's result is on disk before the figure is drawn
  // of the last step, written just above or in the loop
  draw_figure(moving.empty() ? "" : fmt::format("not at rest at step {}", model.steps()));
  return summary;
}

}  // namespace hydrodda::run
