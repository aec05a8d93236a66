#include "run/run_summary.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "run/model_building.hpp"
#include "hydro/darcy_solver.hpp"
#include "hydro/region_flow.hpp"
#include "hydro/region_tensor.hpp"

namespace hydrodda::run {

using geometry::Point;

std::string describe_unreached_displacement(const scenario::Scenario& s, const dda::System& system) {
  // 1% of the prescribed value, or the penetration tolerance (the precision contacts are held
  // to; a point held at zero drifts by the springs' error, 1e-8 m in the six-block model), or
  // 1% of what its block's own elasticity moves it under the block's stress (the springs yield
  // some 500 times less than that: a side held at zero against a 14 MPa in-situ stress yields
  // 11 µm, against 5.6 mm of the block's own strain). A block lagging behind its springs
  // through its inertia is unstressed, and fails.
  constexpr double kReached = 0.01;
  for (const dda::System::PrescribedProgress& p : system.prescribed_progress()) {
    const double asked = geometry::norm(p.target);
    const double off = geometry::norm(p.reached - p.target);
    if (off <= std::max({kReached * asked, system.penetration_tolerance(), kReached * p.elastic_scale})) continue;
    return fmt::format("the prescribed displacement at ({:g}, {:g}) was not reached: asked ({:.4g}, {:.4g}) m at "
                       "t = {:g} s, reached ({:.4g}, {:.4g}) m; with mechanics.time_step = {:g} s the blocks' inertia "
                       "outweighs the springs that impose it: use a larger time_step",
                       p.point.x, p.point.y, p.target.x, p.target.y, system.time(), p.reached.x, p.reached.y,
                       s.mechanics->time_step);
  }
  return {};
}

std::string block_material_name(const scenario::Scenario& s, const dda::System& system, int block) {
  const int material = system.material(block);
  return material >= 0 && material < static_cast<int>(s.materials.size()) ? s.materials[material].name : "";
}

output::RunSummary summarise_mechanics(const scenario::Scenario& s, const dda::System& system) {
  output::RunSummary summary;
  summary.title = s.title;
  summary.scenario = s.file.string();
  for (int b = 0; b < system.block_count(); ++b) {
    const Point c = system.centroid(b);
    const Point u = system.displacement(b);
    summary.blocks.push_back({b, {c.x, c.y}, {u.x, u.y}, system.rotation(b), system.stress(b), system.area(b),
                              block_material_name(s, system, b)});
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

std::vector<RegionReference> reference_regions(const scenario::Scenario& s, const mesh::TriangleMesh& mesh, double load_time) {
  std::vector<RegionReference> references;
  if (s.flow->regions.empty()) return references;
  hydro::DarcySolver solver(mesh, build_flow_problem(*s.flow, load_time));
  const hydro::FlowSolution matrix = solver.solve(compute_matrix_permeability(s, mesh));
  double head_scale = 0.0;  // the largest |h| of the unfractured case
  for (double h : matrix.head) head_scale = std::max(head_scale, std::abs(h));
  for (const scenario::FlowRegion& r : s.flow->regions) {
    RegionReference reference;
    reference.triangles = select_triangles_in(mesh, r.polygon);
    if (!reference.triangles.empty()) {
      // Measured along the head gradient the boundary conditions impose: along the mean flux
      // instead, the flux's tilt by the fractures would change what is measured.
      const hydro::RegionFlow unfractured = hydro::compute_region_flow(mesh, matrix, reference.triangles);
      // Still water imposes none: its gradient is round-off, at most ~1e-16 of the heads.
      const double drop = geometry::norm(unfractured.mean_head_gradient) * std::hypot(unfractured.length, unfractured.width);
      if (drop > 1e-12 * head_scale) {
        reference.imposed = unfractured.mean_head_gradient;
        reference.matrix_conductivity =
            hydro::compute_region_flow(mesh, matrix, reference.triangles, reference.imposed).effective_conductivity;
      }
    }
    references.push_back(std::move(reference));
  }
  return references;
}

std::vector<std::optional<output::RegionSummary>> summarise_regions(const scenario::Scenario& s,
                                                                  const mesh::TriangleMesh& mesh,
                                                                  const hydro::FlowSolution& solution,
                                                                  std::span<const RegionReference> references,
                                                                  hydro::PermeabilityView permeability) {
  std::vector<std::optional<output::RegionSummary>> regions;
  // The conductivity of every element, made only when some region needs its tensor.
  std::vector<hydro::Conductivity> conductivity;
  const bool tensors_wanted =
      permeability.size() > 0 &&
      std::any_of(references.begin(), references.end(), [](const RegionReference& r) { return !r.triangles.empty(); });
  if (tensors_wanted) {
    const double per_permeability = build_flow_problem(*s.flow, 0.0).fluid.conductivity_per_permeability();
    conductivity.resize(permeability.size());
    for (std::size_t e = 0; e < conductivity.size(); ++e) {
      const hydro::PermeabilityTensor k = permeability[e];
      conductivity[e] = {k.xx * per_permeability, k.xy * per_permeability, k.yy * per_permeability};
    }
  }
  for (std::size_t i = 0; i < references.size(); ++i) {
    const RegionReference& reference = references[i];
    if (reference.triangles.empty()) {
      regions.emplace_back();
      continue;
    }
    const hydro::RegionFlow region = hydro::compute_region_flow(mesh, solution, reference.triangles, reference.imposed);
    output::RegionSummary summary;
    summary.name = s.flow->regions[i].name;
    summary.flow = region.flow;
    if (reference.imposed) {
      summary.effective_conductivity = region.effective_conductivity;
      summary.matrix_conductivity = reference.matrix_conductivity;
      summary.normalised_conductivity = region.effective_conductivity / reference.matrix_conductivity;
      summary.direction = {region.direction.x, region.direction.y};
    }
    if (!conductivity.empty()) {
      const hydro::EffectiveTensor t = hydro::compute_region_tensor(mesh, conductivity, reference.triangles);
      summary.tensor = {t.tensor.xx, t.tensor.xy, t.tensor.yy};
      summary.principal_values = t.principal;
      for (int j = 0; j < 2; ++j) summary.principal_directions[j] = {t.directions[j].x, t.directions[j].y};
    }
    regions.push_back(summary);
  }
  return regions;
}

output::FlowSummary summarise_flow(const scenario::Scenario& s, const mesh::TriangleMesh& mesh,
                                   const hydro::FlowSolution& solution, std::span<const RegionReference> references,
                                   hydro::PermeabilityView permeability) {
  output::FlowSummary flow;
  for (const hydro::BoundaryFlow& b : solution.boundary_flows) flow.boundaries.push_back({b.name, b.flow});
  flow.balance = solution.balance_error;
  const auto regions = summarise_regions(s, mesh, solution, references, permeability);
  for (std::size_t i = 0; i < regions.size(); ++i) {
    if (!regions[i]) {
      spdlog::warn("flow region \"{}\" holds no element: nothing to report", s.flow->regions[i].name);
      continue;
    }
    if (!regions[i]->effective_conductivity)
      spdlog::warn("flow region \"{}\": the boundary heads impose no head gradient across it (still water), so it has "
                   "no effective conductivity along one (null in summary.json); its conductivity_tensor is given",
                   s.flow->regions[i].name);
    flow.regions.push_back(*regions[i]);
  }
  return flow;
}

}  // namespace hydrodda::run
