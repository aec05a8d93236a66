#include <fmt/format.h>

#include "run/figures.hpp"
#include "run/flow_model.hpp"
#include "run/paraview_output.hpp"
#include "run/runs.hpp"

namespace hydrodda::run {

output::RunSummary run_flow(const RunContext& context) {
  std::optional<UnstoppableStage> building(context.callbacks);  // nothing is written before the solve ends
  FlowModel model(context.scenario, context.mesh_cache);
  const std::optional<FractureState> no_fractures;
  const TellModelAtEnd tell_model_at_end(context.callbacks, model, no_fractures);
  const hydro::FlowSolution& solution = model.solve();
  building.reset();
  ProgressReport report;
  report.kind = ProgressReport::Kind::flow_solve;
  report.count = 1;
  report.balance_error = solution.balance_error;
  report.message = fmt::format("flow solved: balance error {:.2e}", solution.balance_error);
  context.report(report);

  output::RunSummary summary = model.summary();
  summary.timings = model.timings();
  summary.converged = true;  // one linear solve: nothing to iterate
  summary.iterations = 1;
  const std::vector<double> no_porosity;
  ParaviewOutput(context.folder, context.scenario.output.fields).write_fluid(0, 0.0, model.mesh(), solution, no_porosity, model.permeability());
  context.write_summary(summary);  // the run's result is on disk before the figures are drawn
  draw_figures(context.scenario, context.folder,
               {model.mesh(), solution, no_porosity, model.permeability(), model.blocks()});
  return summary;
}

}  // namespace hydrodda::run
