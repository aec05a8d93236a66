#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>

#include "cli/interrupt.hpp"
#include "cli/model_building.hpp"
#include "cli/runs.hpp"
#include "coupling/staggered_loop.hpp"
#include "dda/system.hpp"
#include "hydro/region_flow.hpp"
#include "output/csv_table.hpp"
#include "output/field_figure.hpp"

namespace hydrodda::cli {

namespace {

using geometry::Point;
using output::CsvTable;
using Clock = std::chrono::steady_clock;

output::RunSummary summarise(const scenario::Scenario& s, const dda::System& system) {
  output::RunSummary summary;
  summary.title = s.title;
  summary.scenario = s.file.string();
  for (int b = 0; b < system.block_count(); ++b) {
    const Point c = system.centroid(b);
    const Point u = system.displacement(b);
    summary.blocks.push_back({b, {c.x, c.y}, {u.x, u.y}, system.rotation(b), system.stress(b), system.area(b)});
  }
  const auto positions = system.measured_positions();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Point start = s.mechanics->measures[i].point;
    summary.measures.push_back({s.mechanics->measures[i].name,
                                {positions[i].x, positions[i].y},
                                {positions[i].x - start.x, positions[i].y - start.y}});
  }
  return summary;
}

output::FlowSummary summarise_flow(const scenario::Scenario& s, const mesh::TriangleMesh& mesh,
                                   const hydro::FlowSolution& solution) {
  output::FlowSummary flow;
  for (const hydro::BoundaryFlow& b : solution.boundary_flows) flow.boundaries.push_back({b.name, b.flow});
  flow.balance = solution.balance_error;
  for (const scenario::FlowRegion& r : s.flow->regions) {
    const std::vector<int> triangles = select_triangles_in(mesh, r.polygon);
    if (triangles.empty()) continue;
    const hydro::RegionFlow region = hydro::compute_region_flow(mesh, solution, triangles);
    flow.regions.push_back({r.name, region.flow, region.effective_conductivity});
  }
  return flow;
}

// The paper's view of the result: heads with contours, the deformed blocks and the flux; and
// the porosity and permeability maps the last pass computed.
void draw_figures(const scenario::Scenario& s, const output::RunFolder& folder, const mesh::TriangleMesh& mesh,
                  const coupling::StaggeredLoop& loop, const dda::System& system) {
  if (s.output.figures.empty()) return;
  std::vector<geometry::Polygon> blocks;
  for (int b = 0; b < system.block_count(); ++b) blocks.push_back(system.polygon(b));
  const std::filesystem::path dir = folder.figures();
  for (const std::string& format : s.output.figures) {
    output::FieldFigure head;
    head.title = s.title;
    head.field_label = "hydraulic head (m)";
    head.nodes = mesh.nodes;
    head.triangles = mesh.triangles;
    head.node_field = loop.flow().head;
    head.blocks = blocks;
    head.element_flux = loop.flow().flux;
    output::render_field_figure(dir / ("head." + format), head);

    output::FieldFigure porosity;
    porosity.title = "Equivalent porosity";
    porosity.field_label = "porosity";
    porosity.nodes = mesh.nodes;
    porosity.triangles = mesh.triangles;
    porosity.element_field = loop.porosity().porosity;
    porosity.blocks = blocks;
    output::render_field_figure(dir / ("porosity." + format), porosity);

    output::FieldFigure permeability = porosity;
    permeability.title = "Permeability";
    permeability.field_label = "permeability (m2, log scale)";
    permeability.element_field = loop.permeability();
    permeability.logarithmic = true;
    output::render_field_figure(dir / ("permeability." + format), permeability);
  }
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
  settings.max_iterations = s.coupling.max_iterations;
  settings.relaxation = s.coupling.relaxation;
  settings.steps_per_pass = s.mechanics->steps.value_or(
      static_cast<int>(std::ceil(*s.mechanics->end_time / s.mechanics->time_step)));
  settings.permeability = make_permeability_model(s);
  settings.fixed_permeability = find_fixed_permeability(s, mesh);
  coupling::StaggeredLoop loop(mesh, build_flow_problem(*s.flow), system, settings);

  std::vector<std::string> columns{"iteration", "time", "head_change", "displacement_change",
                                   "largest_opening", "mean_porosity", "max_permeability"};
  for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) columns.push_back("flow_" + bc.name);
  CsvTable history(columns);

  double porosity_s = 0, flow_s = 0, forces_s = 0, mechanics_s = 0;
  bool converged = false;
  const auto current_summary = [&] {
    output::RunSummary summary = summarise(s, system);
    if (loop.iterations() > 0) summary.flow = summarise_flow(s, mesh, loop.flow());
    summary.iterations = loop.iterations();
    summary.timings = {{"mesh", mesh_seconds}, {"porosity", porosity_s}, {"flow", flow_s},
                       {"forces", forces_s}, {"mechanics", mechanics_s}};
    return summary;
  };
  try {
    for (int k = 0; k < settings.max_iterations && !converged; ++k) {
      if (interrupt_requested())
        throw RunFailure(fmt::format("interrupted after coupling iteration {}", loop.iterations()), current_summary());
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
      context.folder.write("history.csv", history.text());
      context.progress.update(fmt::format("iteration {}: head change {:.2e}, displacement change {:.2e}",
                                          r.iteration, r.head_change, r.displacement_change));
      spdlog::debug("iteration {}: head change {:.3e}, displacement change {:.3e}", r.iteration, r.head_change,
                    r.displacement_change);
      converged = r.converged;
    }
  } catch (const RunFailure&) {
    throw;
  } catch (const std::exception& e) {
    throw RunFailure(fmt::format("coupling iteration {} failed: {}", loop.iterations(), e.what()), current_summary());
  }
  context.progress.finish();
  draw_figures(s, context.folder, mesh, loop, system);
  output::RunSummary summary = current_summary();
  summary.converged = converged;
  if (!converged)
    spdlog::warn("the coupling loop did not converge in {} iterations (tolerance {:g})", settings.max_iterations,
                 settings.tolerance);
  return summary;
}

}  // namespace hydrodda::cli
