#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>

#include "run/figures.hpp"
#include "run/paraview_output.hpp"
#include "run/model_building.hpp"
#include "run/run_summary.hpp"
#include "cli/runs.hpp"
#include "coupling/local_aperture.hpp"
#include "coupling/permeability_model.hpp"
#include "coupling/porosity.hpp"
#include "hydro/darcy_solver.hpp"
#include "hydro/region_flow.hpp"
#include "mesh/mesh_request.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::cli {

using namespace hydrodda::run;  // the run layer, while the runs still live here

namespace {

using geometry::Point;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// k per triangle: the last region containing it that fixes a permeability (later regions take
// precedence, as in the mesh's region tags); elsewhere from the porosity the blocks leave open.
std::vector<double> assign_permeability(const scenario::Scenario& s, const mesh::TriangleMesh& mesh,
                                        const std::vector<dda::BlockDefinition>& blocks) {
  const std::vector<std::optional<double>> fixed = find_fixed_permeability(s, mesh);
  const bool all_fixed = std::all_of(fixed.begin(), fixed.end(), [](const auto& k) { return k.has_value(); });
  std::vector<double> k(mesh.triangle_count(), 0.0);
  if (all_fixed) {
    for (int t = 0; t < mesh.triangle_count(); ++t) k[t] = *fixed[t];
    return k;
  }
  const scenario::MaterialDefinition& material = s.materials.front();
  std::vector<geometry::Polygon> polygons;
  for (const auto& b : blocks) polygons.push_back(b.polygon);
  const coupling::PorosityMapper mapper(mesh.nodes, mesh.triangles);
  coupling::PorosityField porosity;
  if (polygons.empty()) {
    // No block geometry (a user's mesh alone): intact rock of the matrix porosity everywhere,
    // not the open space an empty block set would mean to the mapper.
    porosity.fracture_area.assign(mesh.triangles.size(), 0.0);
    porosity.porosity.assign(mesh.triangles.size(), material.matrix_porosity);
  } else {
    porosity = mapper.compute(polygons, material.matrix_porosity);
  }
  const coupling::PermeabilityModel model = make_permeability_model(s);
  std::vector<double> apertures;
  if (model.law == coupling::PermeabilityLaw::cubic) {
    std::vector<geometry::Point> centroids;
    for (int t = 0; t < mesh.triangle_count(); ++t) centroids.push_back(mesh::triangle_centroid(mesh, t));
    apertures = coupling::compute_local_apertures(centroids, porosity.fracture_area, polygons, model.domain,
                                                  model.aperture_reach);
  }
  const std::vector<double> from_porosity = model.compute(porosity, mapper.element_areas(), apertures);
  for (int t = 0; t < mesh.triangle_count(); ++t) k[t] = fixed[t] ? *fixed[t] : from_porosity[t];
  return k;
}

}  // namespace

output::RunSummary run_flow(const RunContext& context) {
  const scenario::Scenario& s = context.scenario;
  output::RunSummary summary;
  summary.title = s.title;
  summary.scenario = s.file.string();

  auto start = Clock::now();
  const mesh::TriangleMesh mesh = build_mesh(s);
  summary.timings.push_back({"mesh", seconds_since(start)});
  spdlog::info("mesh: {} nodes, {} triangles", mesh.node_count(), mesh.triangle_count());

  start = Clock::now();
  const std::vector<dda::BlockDefinition> blocks = build_blocks(s);
  const std::vector<double> permeability = assign_permeability(s, mesh, blocks);
  summary.timings.push_back({"permeability", seconds_since(start)});

  start = Clock::now();
  hydro::DarcySolver solver(mesh, build_flow_problem(*s.flow));
  const hydro::FlowSolution solution = solver.solve(permeability);
  summary.timings.push_back({"flow", seconds_since(start)});
  context.progress.update(fmt::format("flow solved: balance error {:.2e}", solution.balance_error));
  context.progress.finish();

  summary.flow = summarise_flow(s, mesh, solution, solve_matrix_flow(s, mesh));
  std::vector<geometry::Polygon> polygons;
  for (const auto& b : blocks) polygons.push_back(b.polygon);
  const std::vector<double> no_porosity;
  draw_figures(s, context.folder, {mesh, solution, no_porosity, permeability, polygons});
  ParaviewOutput(context.folder).write_fluid(0, 0.0, mesh, solution, no_porosity, permeability);
  summary.converged = true;  // one linear solve: nothing to iterate
  summary.iterations = 1;
  return summary;
}

}  // namespace hydrodda::cli
