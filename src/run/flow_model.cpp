#include "run/flow_model.hpp"

#include "scenario/load_times.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <stdexcept>

#include "run/model_building.hpp"
#include "run/permeability_cap.hpp"
#include "run/run_summary.hpp"
#include "coupling/local_aperture.hpp"
#include "coupling/permeability_model.hpp"
#include "coupling/porosity.hpp"
#include "hydro/darcy_solver.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::run {

namespace {

using geometry::Point;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// k per triangle: the last region containing it that fixes a permeability (later regions take
// precedence, as in the mesh's region tags); elsewhere from the porosity the blocks leave open.
std::vector<double> assign_permeability(const scenario::Scenario& s, const mesh::TriangleMesh& mesh,
                                        const std::vector<geometry::Polygon>& polygons) {
  const std::vector<std::optional<double>> fixed = find_fixed_permeability(s, mesh);
  const bool all_fixed = std::all_of(fixed.begin(), fixed.end(), [](const auto& k) { return k.has_value(); });
  std::vector<double> k(mesh.triangle_count(), 0.0);
  if (all_fixed) {
    for (int t = 0; t < mesh.triangle_count(); ++t) k[t] = *fixed[t];
    return k;
  }
  const coupling::PermeabilityModel model = make_element_permeability_model(s, mesh);
  const coupling::PorosityMapper mapper(mesh.nodes, mesh.triangles);
  coupling::PorosityField porosity;
  if (polygons.empty()) {
    // No block geometry (a user's mesh alone): intact rock of the matrix porosity everywhere,
    // not the open space an empty block set would mean to the mapper.
    porosity.fracture_area.assign(mesh.triangles.size(), 0.0);
    porosity.porosity.assign(mesh.triangles.size(), model.matrix_porosity);
  } else {
    porosity = mapper.compute(polygons, model.matrix_porosity);
  }
  // Materials by region: each element's equivalent porosity on its own material's matrix.
  for (std::size_t e = 0; e < model.element_matrix_porosity.size(); ++e)
    porosity.porosity[e] = coupling::equivalent_porosity(porosity.fracture_area[e], mapper.element_areas()[e],
                                                         model.element_matrix_porosity[e]);
  std::vector<double> apertures;
  if (model.reads_apertures())
    apertures = coupling::compute_local_apertures(mesh, porosity.fracture_area, polygons, model.domain,
                                                  model.aperture_reach);
  const std::vector<double> from_porosity = model.compute(porosity, mapper.element_areas(), apertures);
  std::vector<int> capped;
  for (int e : model.find_capped_elements(porosity, mapper.element_areas(), apertures))
    if (!fixed[e]) capped.push_back(e);
  if (const auto text = describe_capped_fractures(capped, mesh, {}, model.fracture_cap)) spdlog::warn("{}", *text);
  for (int t = 0; t < mesh.triangle_count(); ++t) k[t] = fixed[t] ? *fixed[t] : from_porosity[t];
  return k;
}

}  // namespace

FlowModel::FlowModel(const scenario::Scenario& scenario, const std::optional<std::filesystem::path>& mesh_cache)
    : scenario_(scenario) {
  auto start = Clock::now();
  mesh_ = build_mesh(scenario_, mesh_cache);
  timings_.push_back({"mesh", seconds_since(start)});
  spdlog::info("mesh: {} nodes, {} triangles", mesh_.node_count(), mesh_.triangle_count());

  start = Clock::now();
  for (const dda::BlockDefinition& b : build_blocks(scenario_)) blocks_.push_back(b.polygon);
  permeability_ = assign_permeability(scenario_, mesh_, blocks_);
  timings_.push_back({"permeability", seconds_since(start)});
}

void FlowModel::set_flow_boundaries(std::vector<scenario::FlowBoundaryCondition> boundaries) {
  scenario_.flow->boundaries = std::move(boundaries);
  solution_ = {};
}

const hydro::FlowSolution& FlowModel::solve() {
  const auto start = Clock::now();
  hydro::DarcySolver solver(mesh_, build_flow_problem(*scenario_.flow, scenario::find_final_load_time(scenario_)));
  solution_ = solver.solve(permeability_);
  const double seconds = seconds_since(start);
  if (timings_.back().name == "flow") timings_.back().value += seconds;
  else timings_.push_back({"flow", seconds});
  return solution_;
}

output::RunSummary FlowModel::summary() const { return summary(scenario::find_final_load_time(scenario_)); }

output::RunSummary FlowModel::summary(double time) const {
  if (solution_.head.empty()) throw std::logic_error("FlowModel::summary: nothing has been solved yet");
  output::RunSummary summary;
  summary.title = scenario_.title;
  summary.scenario = scenario_.file.string();
  summary.flow = summarise_flow(scenario_, mesh_, solution_, reference_regions(scenario_, mesh_, time),
                                hydro::PermeabilityView(permeability_));
  return summary;
}

}  // namespace hydrodda::run
