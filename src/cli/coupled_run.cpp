#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <utility>

#include "run/figures.hpp"
#include "cli/interrupt.hpp"
#include "run/paraview_output.hpp"
#include "run/model_building.hpp"
#include "run/run_summary.hpp"
#include "cli/runs.hpp"
#include "coupling/staggered_loop.hpp"
#include "dda/system.hpp"
#include "hydro/region_flow.hpp"
#include "output/csv_table.hpp"

namespace hydrodda::cli {

using namespace hydrodda::run;  // the run layer, while the runs still live here

namespace {

using geometry::Point;
using output::CsvTable;
using Clock = std::chrono::steady_clock;

// The changes of every pass from history.csv's rows (columns iteration, time, head_change,
// displacement_change, ...), those of a resumed run's earlier passes included.
ConvergenceHistory read_convergence(const std::vector<std::vector<std::string>>& rows, double tolerance) {
  ConvergenceHistory h;
  h.tolerance = tolerance;
  for (const std::vector<std::string>& row : rows) {
    h.iteration.push_back(std::stod(row[0]));
    h.head_change.push_back(std::stod(row[2]));
    h.displacement_change.push_back(std::stod(row[3]));
  }
  return h;
}

}  // namespace

output::RunSummary run_coupled(const RunContext& context) {
  const scenario::Scenario& s = context.scenario;
  double mesh_seconds = 0.0;
  auto start = Clock::now();
  const mesh::TriangleMesh mesh = build_mesh(s);
  mesh_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  spdlog::info("mesh: {} nodes, {} triangles", mesh.node_count(), mesh.triangle_count());

  dda::System system(build_mechanics_model(s, build_blocks(s)));
  spdlog::info("mechanics: {} blocks", system.block_count());

  coupling::LoopSettings settings;
  settings.tolerance = s.coupling.tolerance;
  settings.relaxation = s.coupling.relaxation;
  settings.steps_per_pass = s.mechanics->steps.value_or(
      static_cast<int>(std::ceil(*s.mechanics->end_time / s.mechanics->time_step)));
  settings.permeability = make_permeability_model(s);
  settings.fixed_permeability = find_fixed_permeability(s, mesh);
  settings.stop_requested = interrupt_requested;
  coupling::StaggeredLoop loop(mesh, build_flow_problem(*s.flow), system, settings);
  // The unfractured case does not change between passes: solved once.
  const std::optional<hydro::FlowSolution> matrix_flow = solve_matrix_flow(s, mesh);

  std::vector<std::string> columns{"iteration", "time", "head_change", "displacement_change",
                                   "largest_opening", "mean_porosity", "max_permeability"};
  for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) columns.push_back("flow_" + bc.name);
  CsvTable history(columns);

  // What a checkpoint holds besides the engines' states; restored first when resuming.
  output::RunCheckpoint checkpoint;
  checkpoint.scenario_hash = output::hash_text(context.scenario_text);
  checkpoint.scenario_file = std::filesystem::absolute(s.file).string();
  double porosity_s = 0, flow_s = 0, forces_s = 0, mechanics_s = 0;
  ParaviewOutput paraview(context.folder);
  if (context.resume) {
    const output::RunCheckpoint& saved = *context.resume;
    system.import_state(saved.mechanics);
    loop.import_state(saved.coupling);
    checkpoint.mechanics = saved.mechanics;
    checkpoint.coupling = saved.coupling;
    checkpoint.history = saved.history;
    checkpoint.written_iterations = saved.written_iterations;
    for (const std::vector<std::string>& row : saved.history) history.add_row(row);
    paraview.list_written(saved.written_iterations);
    for (const auto& [phase, seconds] : saved.timings) {
      for (auto [name, total] : {std::pair{"mesh", &mesh_seconds}, std::pair{"porosity", &porosity_s},
                                 std::pair{"flow", &flow_s}, std::pair{"forces", &forces_s},
                                 std::pair{"mechanics", &mechanics_s}})
        if (phase == name) *total += seconds;
    }
    spdlog::info("resuming after coupling iteration {}", loop.iterations());
  } else {
    context.folder.write("scenario.toml", context.scenario_text);
  }

  const auto write_fields = [&](int iteration) {
    paraview.write_fluid(iteration, iteration, mesh, loop.flow(), loop.porosity().porosity, loop.permeability());
    paraview.write_blocks(iteration, iteration, system);
    checkpoint.written_iterations.push_back(iteration);
  };
  int last_written = checkpoint.written_iterations.empty() ? 0 : checkpoint.written_iterations.back();
  bool converged = false;
  bool stopped = false;  // by --stop-after
  const auto current_summary = [&] {
    output::RunSummary summary = summarise_mechanics(s, system);
    if (loop.has_flow()) summary.flow = summarise_flow(s, mesh, loop.flow(), matrix_flow);
    summary.iterations = loop.iterations();
    summary.timings = {{"mesh", mesh_seconds}, {"porosity", porosity_s}, {"flow", flow_s},
                       {"forces", forces_s}, {"mechanics", mechanics_s}};
    return summary;
  };
  // After every finished pass: the checkpoint, then the engines continue from exactly what it
  // holds, as a resumed run does (importing also restarts the DDA linear solver, whose reused
  // factors would otherwise carry round-off history that no checkpoint holds).
  const auto save_checkpoint = [&] {
    checkpoint.converged = converged;
    checkpoint.timings = {{"mesh", mesh_seconds}, {"porosity", porosity_s}, {"flow", flow_s},
                          {"forces", forces_s}, {"mechanics", mechanics_s}};
    checkpoint.mechanics = system.export_state();
    checkpoint.coupling = loop.export_state();
    context.folder.write("checkpoint.bin", output::encode_checkpoint(checkpoint));
    system.import_state(checkpoint.mechanics);
  };
  const dda::SystemState initial_mechanics = system.export_state();
  try {
    for (int k = loop.iterations(); k < s.coupling.max_iterations && !converged; ++k) {
      if (interrupt_requested())
        throw RunFailure(fmt::format("interrupted after coupling iteration {}", loop.iterations()), current_summary());
      if (context.stop_after && loop.iterations() >= *context.stop_after) {
        stopped = true;
        break;
      }
      const coupling::PassReport r = loop.run_pass();
      porosity_s += r.porosity_seconds;
      flow_s += r.flow_seconds;
      forces_s += r.forces_seconds;
      mechanics_s += r.mechanics_seconds;
      std::vector<std::string> row{CsvTable::cell(static_cast<long long>(r.iteration)), CsvTable::cell(r.time),
                                   CsvTable::cell(r.head_change), CsvTable::cell(r.displacement_change),
                                   CsvTable::cell(r.largest_opening), CsvTable::cell(r.mean_porosity),
                                   CsvTable::cell(r.max_permeability)};
      for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries)
        row.push_back(CsvTable::cell(loop.flow().boundary_flow(bc.name)));
      history.add_row(row);
      checkpoint.history.push_back(row);
      context.folder.write("history.csv", history.text());
      context.progress.update(fmt::format("iteration {}: head change {:.2e}, displacement change {:.2e}",
                                          r.iteration, r.head_change, r.displacement_change));
      spdlog::debug("iteration {}: head change {:.3e}, displacement change {:.3e}", r.iteration, r.head_change,
                    r.displacement_change);
      converged = r.converged;
      if (r.iteration % s.output.every == 0 || converged || r.diverging) {
        write_fields(r.iteration);
        last_written = r.iteration;
      }
      save_checkpoint();
      if (r.diverging) {
        throw RunFailure(fmt::format("the coupling loop diverges: its change grew {} passes in a row, to a head "
                                     "change of {:.3e} and a displacement change of {:.3e} at coupling iteration {}",
                                     r.growing_passes, r.head_change, r.displacement_change, r.iteration),
                         current_summary());
      }
    }
    // The last state's fields, unless the run is to be continued (it writes them at its end).
    if (!stopped && loop.iterations() > 0 && last_written != loop.iterations()) {
      write_fields(loop.iterations());
      save_checkpoint();
    }
  } catch (const RunFailure&) {
    throw;
  } catch (const coupling::PassInterrupted& e) {
    // Back to the last finished pass, the state the run folder and the checkpoint hold (before
    // the first pass: the blocks as built), so that summary.json describes it.
    if (loop.iterations() > 0) {
      system.import_state(checkpoint.mechanics);
      loop.import_state(checkpoint.coupling);
    } else {
      system.import_state(initial_mechanics);
    }
    throw RunFailure(fmt::format("interrupted: {}; the results are those of coupling iteration {}", e.what(),
                                 loop.iterations()),
                     current_summary());
  } catch (const std::exception& e) {
    throw RunFailure(fmt::format("coupling iteration {} failed: {}", loop.iterations() + 1, e.what()), current_summary());
  }
  context.progress.finish();
  if (stopped) {
    output::RunSummary summary = current_summary();
    summary.status = "stopped";
    summary.message = fmt::format("stopped after coupling iteration {} (--stop-after)", loop.iterations());
    return summary;
  }
  std::vector<geometry::Polygon> blocks;
  for (int b = 0; b < system.block_count(); ++b) blocks.push_back(system.polygon(b));
  draw_figures(s, context.folder, {mesh, loop.flow(), loop.porosity().porosity, loop.permeability(), blocks});
  draw_convergence(s, context.folder, read_convergence(checkpoint.history, settings.tolerance));
  output::RunSummary summary = current_summary();
  summary.converged = converged;
  if (!converged)
    spdlog::warn("the coupling loop did not converge in {} iterations (tolerance {:g})", s.coupling.max_iterations,
                 settings.tolerance);
  return summary;
}

}  // namespace hydrodda::cli
