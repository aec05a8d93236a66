#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coupling/porosity.hpp"
#include "hydro/fluid.hpp"
#include "mesh/point_locator.hpp"
#include "run/transient_flow.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/scenario_queries.hpp"

namespace hydrodda::run {

std::vector<double> plan_step_times(const scenario::TransientDefinition& transient,
                                    const std::vector<double>& row_times) {
  const double end = transient.end_time;
  if (!(end > 0.0) || !(transient.time_step > 0.0) || !(transient.max_time_step >= transient.time_step))
    throw std::invalid_argument("plan_step_times: the transient's times are not those the reader accepts");
  // The times a step must end on: the output times and table rows after 0, and the end.
  std::vector<double> stops;
  for (const std::vector<double>* times : {&transient.output_times, &row_times})
    for (double t : *times)
      if (t > 0.0 && t < end) stops.push_back(t);
  std::sort(stops.begin(), stops.end());
  stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
  stops.push_back(end);
  std::vector<double> times;
  double t = 0.0, nominal = transient.time_step;
  std::size_t next_stop = 0;
  while (t < end) {
    const double stop = stops[next_stop];
    // Within a millionth of a step of the stop: end there rather than leave a sliver of a step.
    if (t + nominal >= stop - 1e-6 * nominal) {
      t = stop;
      ++next_stop;
    } else {
      t += nominal;
    }
    times.push_back(t);
    nominal = std::min(nominal * kTimeStepGrowth, transient.max_time_step);
  }
  return times;
}

std::vector<double> compute_specific_storage(const scenario::Scenario& s, const mesh::TriangleMesh& mesh,
                                             const std::vector<geometry::Polygon>& blocks) {
  const double unit_weight = s.flow->fluid_density * hydro::Fluid{}.gravity;  // ρ_w g
  // The open fraction of each element: none without blocks (a user's mesh alone is rock).
  std::vector<double> open(mesh.triangles.size(), 0.0);
  if (!blocks.empty() && s.flow->fluid_compressibility > 0.0) {
    const coupling::PorosityMapper mapper(mesh.nodes, mesh.triangles);
    const coupling::PorosityField field = mapper.compute(blocks, 0.0);
    for (std::size_t e = 0; e < open.size(); ++e)
      open[e] = std::clamp(field.fracture_area[e] / mapper.element_areas()[e], 0.0, 1.0);
  }
  std::vector<double> storage(mesh.triangles.size(), 0.0);
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const int material = scenario::find_material_at(s, mesh::triangle_centroid(mesh, t));
    const double rock = material >= 0 ? s.materials[material].storage : 0.0;
    storage[t] = unit_weight * ((1.0 - open[t]) * rock + open[t] * s.flow->fluid_compressibility);
  }
  return storage;
}

std::vector<ProbeSite> locate_probes(const scenario::Scenario& s, const mesh::TriangleMesh& mesh) {
  std::vector<ProbeSite> sites;
  if (s.flow->probes.empty()) return sites;
  const mesh::PointLocator locator(mesh);
  std::vector<scenario::Diagnostic> errors;
  for (const scenario::ProbeDefinition& probe : s.flow->probes) {
    ProbeSite site{probe.name, locator.locate(probe.point), {}};
    if (site.triangle < 0) {
      errors.push_back({s.file.string(), probe.line, "flow.probe.point", "the point lies outside the fluid mesh"});
      continue;
    }
    // Barycentric weights: each corner's share, the area of the triangle the point makes with
    // the other two over the whole.
    const auto& tri = mesh.triangles[site.triangle];
    const geometry::Point a = mesh.nodes[tri[0]], b = mesh.nodes[tri[1]], c = mesh.nodes[tri[2]];
    const double whole = geometry::orient(a, b, c);
    site.weights = {geometry::orient(probe.point, b, c) / whole, geometry::orient(a, probe.point, c) / whole,
                    geometry::orient(a, b, probe.point) / whole};
    sites.push_back(std::move(site));
  }
  if (!errors.empty()) throw scenario::ScenarioError(std::move(errors));
  return sites;
}

double value_at(const ProbeSite& site, const mesh::TriangleMesh& mesh, const std::vector<double>& nodal) {
  const auto& tri = mesh.triangles[site.triangle];
  return site.weights[0] * nodal[tri[0]] + site.weights[1] * nodal[tri[1]] + site.weights[2] * nodal[tri[2]];
}

}  // namespace hydrodda::run
