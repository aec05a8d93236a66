#include <fmt/format.h>

#include "run/figures.hpp"
#include "run/flow_model.hpp"
#include "run/paraview_output.hpp"
#include "output/csv_table.hpp"
#include "run/runs.hpp"
#include "run/transient_flow.hpp"

namespace hydrodda::run {

namespace {

// Between the phases after the solve (fields, summary, figures, which take as long as the solve
// on a large mesh): an interrupt stops the run there, its summary.json saying so.
void stop_if_requested(const RunContext& context, const output::RunSummary& summary, const std::string& where) {
  if (context.stop_requested()) throw RunFailure(RunStatus::interrupted, "interrupted " + where, summary);
}

// probes.csv of a steady run: each probe's head and pressure, with no time (a steady state has none).
void write_steady_probes(const RunContext& context, const FlowModel& model, const hydro::FlowSolution& solution) {
  if (context.scenario.flow->probes.empty()) return;
  output::CsvTable probes({"time", "name", "head", "pressure"});
  for (const ProbeSite& site : locate_probes(context.scenario, model.mesh()))
    probes.add_row({"", site.name, output::CsvTable::cell(value_at(site, model.mesh(), solution.head)),
                    output::CsvTable::cell(value_at(site, model.mesh(), solution.pressure))});
  context.folder.write("probes.csv", probes.text());
}

}  // namespace

output::RunSummary run_flow(const RunContext& context) {
  if (context.scenario.flow->transient) return run_transient_flow(context);
  std::optional<UnstoppableStage> building(context.callbacks);  // nothing is written before the solve ends
  FlowModel model(context.scenario, context.mesh_cache);
  const std::optional<fractures::FractureState> no_fractures;
  const TellModelAtEnd tell_model_at_end(context.callbacks, model, no_fractures);
  const hydro::FlowSolution& solution = model.solve();
  building.reset();
  ProgressReport report;
  report.kind = ProgressReport::Kind::flow_solve;
  report.count = 1;
  report.balance_error = solution.balance_error;
  report.message = fmt::format("flow solved: balance error {:.2e}", solution.balance_error);
  context.report(report);

  output::RunSummary unsummarised;  // summarising a large mesh's flow takes seconds
  unsummarised.title = context.scenario.title;
  unsummarised.scenario = context.scenario.file.string();
  stop_if_requested(context, unsummarised, "after the flow solve, before its results were summarised");
  output::RunSummary summary = model.summary();
  summary.timings = model.timings();
  summary.converged = true;  // one linear solve: nothing to iterate
  summary.iterations = 1;
  stop_if_requested(context, summary, "after the flow solve, before its fields were written");
  const std::vector<double> no_porosity;
  ParaviewOutput(context.folder, context.scenario.output.fields).write_fluid(0, 0.0, model.mesh(), solution, no_porosity, model.permeability());
  write_steady_probes(context, model, solution);
  context.write_summary(summary);  // the run's result is on disk before the figures are drawn
  FlowPicture picture{model.mesh(), solution, no_porosity, model.permeability(), model.blocks()};
  picture.stop_requested = [&context] { return context.stop_requested(); };
  draw_figures(context.scenario, context.folder, picture);
  stop_if_requested(context, summary, "after the results were written, before all figures were drawn");
  return summary;
}

}  // namespace hydrodda::run
