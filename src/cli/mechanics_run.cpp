#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>

#include "cli/interrupt.hpp"
#include "run/paraview_output.hpp"
#include "run/model_building.hpp"
#include "run/run_summary.hpp"
#include "cli/runs.hpp"
#include "dda/system.hpp"
#include "output/csv_table.hpp"

namespace hydrodda::cli {

using namespace hydrodda::run;  // the run layer, while the runs still live here

namespace {

using output::CsvTable;
using geometry::Point;

}  // namespace

output::RunSummary run_mechanics(const RunContext& context) {
  const scenario::Scenario& s = context.scenario;
  const scenario::MechanicsDefinition& m = *s.mechanics;
  const auto start = std::chrono::steady_clock::now();

  dda::System system(build_mechanics_model(s, build_blocks(s)));
  spdlog::info("mechanics: {} blocks, penalty {:.3g} N/m, allowed step displacement {:.3g} m",
               system.block_count(), system.penalty(), system.allowed_step_displacement());

  CsvTable history({"step", "time", "time_step", "open_close_iterations", "contacts",
                    "max_displacement", "max_penetration"});
  CsvTable measure({"step", "time", "name", "x", "y", "ux", "uy"});
  const auto write_tables = [&] {
    context.folder.write("history.csv", history.text());
    if (!m.measures.empty()) context.folder.write("measure.csv", measure.text());
  };

  ParaviewOutput paraview(context.folder);
  paraview.write_blocks(0, 0.0, system);
  long long last_written = 0;
  const double end_time = mechanics_duration(m);
  const int max_steps = m.steps.value_or(0);
  long long step = 0;
  // Time-step control may shorten steps, so a run by `end_time` goes on until that time;
  // a run by `steps` takes exactly that many.
  const auto more = [&] {
    return m.steps ? step < max_steps : system.time() < end_time * (1.0 - 1e-12);
  };
  try {
    while (more()) {
      if (interrupt_requested()) {
        write_tables();
        output::RunSummary summary = summarise_mechanics(s, system);
        summary.iterations = static_cast<int>(step);
        throw RunFailure(fmt::format("interrupted at step {} (t = {:g} s)", step, system.time()), summary);
      }
      const dda::StepReport r = m.steps ? system.step() : system.run_until(std::min(end_time, system.time() + m.time_step));
      ++step;
      history.add_row({CsvTable::cell(step), CsvTable::cell(r.time), CsvTable::cell(r.time_step),
                       CsvTable::cell(static_cast<long long>(r.open_close_iterations)),
                       CsvTable::cell(static_cast<long long>(r.contacts)), CsvTable::cell(r.max_displacement),
                       CsvTable::cell(r.max_penetration)});
      const auto positions = system.measured_positions();
      for (std::size_t i = 0; i < positions.size(); ++i) {
        const Point p0 = m.measures[i].point;
        measure.add_row({CsvTable::cell(step), CsvTable::cell(r.time), m.measures[i].name,
                         CsvTable::cell(positions[i].x), CsvTable::cell(positions[i].y),
                         CsvTable::cell(positions[i].x - p0.x), CsvTable::cell(positions[i].y - p0.y)});
      }
      if (step % 100 == 0) write_tables();
      if (step % s.output.every == 0) {
        paraview.write_blocks(static_cast<int>(step), r.time, system);
        last_written = step;
      }
      context.progress.update(fmt::format("step {} t = {:.4g} s, {} contacts, max step displacement {:.3g} m",
                                          step, r.time, r.contacts, r.max_displacement));
    }
  } catch (const RunFailure&) {
    throw;
  } catch (const std::exception& e) {
    write_tables();
    output::RunSummary summary = summarise_mechanics(s, system);
    summary.iterations = static_cast<int>(step);
    throw RunFailure(fmt::format("mechanics failed at step {} (t = {:g} s): {}", step + 1, system.time(), e.what()),
                     summary);
  }
  write_tables();
  if (last_written != step) paraview.write_blocks(static_cast<int>(step), system.time(), system);
  context.progress.finish();

  output::RunSummary summary = summarise_mechanics(s, system);
  // Mechanics alone has no coupling loop: `converged` says the run reached its end.
  summary.converged = true;
  summary.iterations = static_cast<int>(step);
  summary.timings.push_back(
      {"mechanics", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
  return summary;
}

}  // namespace hydrodda::cli
