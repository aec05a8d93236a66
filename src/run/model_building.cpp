#include "run/model_building.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "dda/selection.hpp"
#include "dda/support.hpp"
#include "numerics/parallel.hpp"
#include "mesh/mesh_cache.hpp"
#include "mesh/mesh_request.hpp"
#include "mesh/spatial_order.hpp"
#include "run/in_situ_check.hpp"
#include "run/joint_barriers.hpp"
#include "run/layered_stress.hpp"
#include "run/mesh_budget.hpp"
#include "run/model_geometry.hpp"
#include "run/sub_blocks.hpp"
#include "hydro/permeability_law.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/scenario_queries.hpp"
#include "scenario/spellings.hpp"

namespace hydrodda::run {

namespace {

using scenario::Diagnostic;
using scenario::Scenario;
using geometry::Point;

// Distance within which a point counts as on a boundary or in a block: a relative 1e-9 of the
// model's size, far below any geometric feature and far above round-off.
double geometric_tolerance(const std::vector<dda::BlockDefinition>& blocks) {
  geometry::Box box;
  for (const auto& b : blocks)
    for (Point p : b.polygon) box.add(p);
  return 1e-9 * std::max(box.width(), box.height());
}

// The block that holds p (inside or on its boundary); -1 when none does.
int find_block(const std::vector<dda::BlockDefinition>& blocks, Point p, double tolerance) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const geometry::Polygon& poly = blocks[i].polygon;
    if (geometry::contains(poly, p)) return static_cast<int>(i);
    for (std::size_t v = 0; v < poly.size(); ++v)
      if (geometry::distance_to_segment(p, poly[v], poly[(v + 1) % poly.size()]) <= tolerance)
        return static_cast<int>(i);
  }
  return -1;
}

// A mechanics-only model whose in-situ stress does not balance the rock's weight
// (∂σyy/∂y + ρ g_y = 0, ∂τxy/∂y + ρ g_x = 0 for a field linear in y) does not start in
// equilibrium: its blocks move at the first step. Said once, as the user may mean it.
void note_unbalanced_initial_stress(const Scenario& s) {
  if (s.flow || s.materials.size() != 1 || !s.materials[0].density) return;
  const scenario::InitialStressDefinition& i = *s.mechanics->initial_stress;
  const double rho = *s.materials[0].density;
  const Point g = s.mechanics->gravity;
  const double weight = rho * std::hypot(g.x, g.y);
  const double off_y = i.gradient[1] + rho * g.y, off_x = i.gradient[2] + rho * g.x;
  if (std::max(std::abs(off_x), std::abs(off_y)) > 0.01 * std::max(weight, 1e-300))
    spdlog::warn("{}:{}: mechanics.initial_stress: the gradient [dσxx/dy, dσyy/dy, dτxy/dy] = [{:g}, {:g}, {:g}] Pa/m does "
                 "not balance the rock's weight (dσyy/dy = {:g}, dτxy/dy = {:g} would): the blocks start out of equilibrium",
                 s.file.string(), i.line, i.gradient[0], i.gradient[1], i.gradient[2], -rho * g.y, -rho * g.x);
}

// Static analysis needs every group of touching blocks held (dda/support.hpp); "some support
// somewhere" let a floating block creep under a point load and the run report success.
void report_unsupported_blocks(const Scenario& s, const dda::ModelDefinition& model, std::vector<Diagnostic>& errors) {
  const double touching = dda::initial_contact_distance(model.blocks, model.settings);
  const bool given_one_by_one = s.geometry && s.geometry->domain.empty();
  for (const std::vector<int>& group : dda::find_unsupported_groups(model, touching)) {
    const int first = group.front();
    const int line = given_one_by_one ? s.geometry->blocks[first].line : 0;
    std::string which = fmt::format("block {}", first);
    if (group.size() > 1)
      which = fmt::format("the group of {} touching blocks {}{}", group.size(),
                          fmt::join(group.begin(), group.begin() + std::min<std::size_t>(group.size(), 5), ", "),
                          group.size() > 5 ? ", ..." : "");
    errors.push_back({s.file.string(), line, "mechanics.analysis",
                      fmt::format("static analysis: {} has no support (no fixed block, [[mechanics.fixed]] point, "
                                  "[[mechanics.displacement]] or [[mechanics.roller]] holds it or a block within "
                                  "{:g} m of it, the contact distance), so a load moves it without end; add a "
                                  "support or use analysis = \"{}\"",
                                  which, touching, scenario::spell(dda::Analysis::dynamic))});
  }
}

int material_index(const Scenario& s, const std::string& name) {
  for (std::size_t i = 0; i < s.materials.size(); ++i)
    if (s.materials[i].name == name) return static_cast<int>(i);
  return 0;
}

}  // namespace

ModelGeometry build_and_log_geometry(const Scenario& s, GeometryWarnings warnings) {
  ModelGeometry model;
  try {
    model = build_model_geometry(s);
  } catch (const scenario::ScenarioError&) {
    throw;
  } catch (const std::runtime_error& e) {
    // Blocks too small for the initial aperture: bad input, refused by `check` as by `run`.
    throw scenario::ScenarioError({{s.file.string(), 0, "geometry.initial_aperture",
                                    fmt::format("{}; make it smaller, or cut fewer blocks", e.what())}});
  }
  if (!s.geometry->min_block_area)
    spdlog::debug("default used: geometry.min_block_area = {:.3g} (1% of the mean block area)", model.network.min_block_area);
  for (const std::string& w : model.warnings) {
    if (warnings == GeometryWarnings::logged) spdlog::warn("{}", w);
    else spdlog::debug("{} (warned once)", w);
  }
  for (const std::string& n : model.notes) spdlog::info("{}", n);
  spdlog::info("geometry: {}", model.summary);
  return model;
}

std::vector<dda::BlockDefinition> blocks_of(const Scenario& s, const ModelGeometry& model) {
  std::vector<dda::BlockDefinition> blocks;
  std::vector<Diagnostic> errors;
  for (std::size_t b = 0; b < model.network.blocks.size(); ++b) {
    const geometry::Polygon& p = model.network.blocks[b];
    const Point c = geometry::centroid(p);
    const int material = s.materials.empty() ? 0 : scenario::find_material_at(s, c);
    if (material < 0 && errors.size() < 5)
      errors.push_back({s.file.string(), s.materials.front().region_line, "material",
                        fmt::format("block {} (centroid ({:g}, {:g})) lies in no material's region, and every "
                                    "material has one: give one material no region to take the rest",
                                    b, c.x, c.y)});
    dda::BlockDefinition block{p, std::max(material, 0), false};
    // Each edge on a trace takes the trace's joint type; one on the domain boundary the default.
    for (int fracture : model.network.edge_fractures[b])
      block.edge_joints.push_back(fracture < 0 ? 0 : model.traces[static_cast<std::size_t>(fracture)].joint_type);
    // A bonded face (a tessellation's) takes its bonds' type.
    if (!model.edge_bonds.empty()) {
      block.edge_bonds = model.edge_bonds[b];
      for (std::size_t e = 0; e < block.edge_bonds.size(); ++e)
        if (block.edge_bonds[e] >= 0) block.edge_joints[e] = model.bond_types[static_cast<std::size_t>(block.edge_bonds[e])];
    }
    blocks.push_back(std::move(block));
  }
  if (!errors.empty()) throw scenario::ScenarioError(std::move(errors));
  return blocks;
}

std::vector<dda::BlockDefinition> build_blocks(const Scenario& s, GeometryWarnings warnings) {
  std::vector<dda::BlockDefinition> blocks;
  if (!s.geometry) return blocks;
  if (!s.geometry->domain.empty()) return blocks_of(s, build_and_log_geometry(s, warnings));
  for (const scenario::BlockDefinition& b : s.geometry->blocks) {
    dda::BlockDefinition block;
    block.polygon = b.vertices;
    block.material = material_index(s, b.material);
    block.fixed = b.fixed;
    blocks.push_back(std::move(block));
  }
  return blocks;
}

hydro::JointApertureLaw make_joint_aperture_law(const scenario::JointDefinition& j) {
  return {j.residual_aperture.value_or(0.0), j.normal_stiffness.value_or(0.0), j.max_closure.value_or(0.0),
          j.hydraulic_opening};
}

coupling::JointApertureLaws make_joint_aperture_laws(const Scenario& s, std::span<const geometry::FractureTrace> traces) {
  // Where no joint conducts by a law of its own (no hydraulic keys, no bonds), the flow sees each
  // gap point by point through the porosity law, and so does fractures.csv's hydraulic aperture.
  const bool by_porosity = !s.any_joint_hydraulic() && !(s.geometry && !s.geometry->tessellations.empty());
  std::vector<hydro::JointApertureLaw> by_type;
  for (int t = 0; t < s.joint_type_count(); ++t) {
    by_type.push_back(make_joint_aperture_law(s.joint_type(t)));
    if (by_porosity) by_type.back().opening = hydro::HydraulicOpening::local;
  }
  std::vector<int> fracture_types;
  for (const geometry::FractureTrace& trace : traces) fracture_types.push_back(trace.joint_type);
  return {std::move(by_type), std::move(fracture_types)};
}

double smallest_joint_zero_stress_aperture(const Scenario& s) {
  double smallest = 0.0;
  for (int t = 0; t < s.joint_type_count(); ++t)
    if (const double a0 = make_joint_aperture_law(s.joint_type(t)).at_zero_stress(); a0 > 0.0)
      smallest = smallest > 0.0 ? std::min(smallest, a0) : a0;
  return smallest;
}

namespace {
// The material whose matrix an element takes where no region says otherwise: the one without a
// region (the only one in a model without regions).
const scenario::MaterialDefinition& find_rest_material(const Scenario& s) {
  for (const scenario::MaterialDefinition& m : s.materials)
    if (m.region.empty()) return m;
  return s.materials.front();
}
}  // namespace

std::vector<int> find_element_materials(const Scenario& s, const mesh::TriangleMesh& mesh) {
  std::vector<int> material(mesh.triangle_count(), -1);
  for (int t = 0; t < mesh.triangle_count(); ++t) material[t] = scenario::find_material_at(s, mesh::triangle_centroid(mesh, t));
  return material;
}

coupling::PermeabilityModel make_permeability_model(const Scenario& s) {
  coupling::PermeabilityModel model;
  const scenario::MaterialDefinition& material = find_rest_material(s);
  model.law = s.flow->permeability_law;
  model.grain_diameter = material.grain_diameter.value_or(0.0);
  model.cap = s.flow->permeability_cap;
  model.fracture_cap = s.flow->fracture_permeability_cap;
  model.matrix_porosity = material.matrix_porosity;
  if (s.geometry) model.domain = s.geometry->domain;
  // Apertures are looked for within the far-field element size: far wider than any fracture.
  model.aperture_reach = s.mesh ? s.mesh->size : 1.0;
  return model;
}

std::optional<std::string> describe_capped_matrix(const Scenario& s) {
  if (!s.flow || s.materials.empty()) return std::nullopt;  // a flow-only model of fixed permeability
  coupling::PermeabilityModel model = make_permeability_model(s);
  // Each material whose matrix the law maps (the first capped one named), the rest's first.
  std::vector<const scenario::MaterialDefinition*> mapped{&find_rest_material(s)};
  for (const scenario::MaterialDefinition& m : s.materials)
    if (&m != mapped.front() && !m.permeability) mapped.push_back(&m);
  for (const scenario::MaterialDefinition* m : mapped) {
    model.matrix_porosity = m->matrix_porosity;
    model.grain_diameter = m->grain_diameter.value_or(0.0);
    if (!model.matrix_capped()) continue;
    const double own = hydro::kozeny_carman_permeability(model.matrix_porosity, model.grain_diameter,
                                                         std::numeric_limits<double>::infinity());
    return fmt::format(
        "material.{}: the Kozeny-Carman permeability of its matrix (matrix_porosity = {:g}, grain_diameter = {:g} m) is "
        "{:.3g} m², above flow.permeability_cap = {:.4g} m², which replaces it in every element of intact rock: raise "
        "flow.permeability_cap above it, or fix the permeability with a [[flow.region]]",
        m->name, model.matrix_porosity, model.grain_diameter, own, model.cap);
  }
  return std::nullopt;
}

std::vector<double> find_biot_coefficients(const Scenario& s, const std::vector<dda::BlockDefinition>& blocks) {
  std::vector<double> biot;
  for (const dda::BlockDefinition& b : blocks) biot.push_back(s.materials[b.material].biot_coefficient);
  return biot;
}

mesh::TriangleMesh read_mesh_file(const Scenario& s) {
  const scenario::MeshDefinition& m = *s.mesh;
  const std::string file = s.file.string();
  mesh::TriangleMesh mesh;
  try {
    mesh = mesh::read_msh(m.file->string());
  } catch (const std::exception& e) {
    // A file that is not a usable triangle mesh is bad input, like a wrong key.
    throw scenario::ScenarioError({{file, m.file_line, "mesh.file", fmt::format("not a usable triangle mesh: {}", e.what())}});
  }
  // The flow boundaries are the file's named physical curves (with edges).
  std::vector<Diagnostic> errors;
  if (s.flow) {
    for (const scenario::FlowBoundaryCondition& bc : s.flow->boundaries) {
      const int b = mesh::find_boundary(mesh, bc.name);
      const bool has_edges = b >= 0 && std::any_of(mesh.boundary_edges.begin(), mesh.boundary_edges.end(),
                                                   [&](const mesh::BoundaryEdge& e) { return e.boundary == b; });
      if (has_edges) continue;
      std::string message = fmt::format("{} has no boundary curve named \"{}\"", m.file->filename().string(), bc.name);
      const std::string nearest = scenario::suggest_nearest(bc.name, mesh.boundary_names);
      if (!nearest.empty()) message += fmt::format(" (did you mean \"{}\"?)", nearest);
      else if (!mesh.boundary_names.empty()) message += fmt::format("; it names: {}", fmt::join(mesh.boundary_names, ", "));
      else message += "; it names no physical curves";
      errors.push_back({file, bc.line, "flow.boundary.name", message});
    }
  }
  if (!errors.empty()) throw scenario::ScenarioError(std::move(errors));
  return mesh;
}

mesh::MeshRequest make_mesh_request(const Scenario& s) {
  const scenario::MeshDefinition& m = *s.mesh;
  mesh::MeshRequest request;
  request.domain = s.geometry->domain;
  for (const scenario::BoundarySegment& b : s.boundaries)
    if (!b.is_default) request.boundaries.push_back({b.name, b.segment.from, b.segment.to});
  for (const geometry::FractureTrace& t : collect_fracture_traces(s))
    request.refinement_lines.push_back({t.segment.from, t.segment.to});
  for (const scenario::FlowRegion& r : s.flow->regions) request.regions.push_back({r.name, r.polygon});
  // The elements honour the materials' regions too, so that each lies in one material.
  for (const scenario::MaterialDefinition& m : s.materials)
    if (!m.region.empty()) request.regions.push_back({"material." + m.name, m.region});
  // Joint barriers: strips the elements follow, after the flow and material regions so that they prevail.
  for (const BarrierStrip& strip : find_barrier_strips(s)) request.regions.push_back({strip.region, strip.polygon});
  request.size = m.size;
  request.fracture_size = m.fracture_size;
  request.refine_distance = m.refine_distance;
  for (const scenario::MeshRefinePoint& r : m.refine_points)
    request.refinement_points.push_back({r.point, r.size, r.radius});
  request.processes = numerics::thread_count();  // the tiles of a large mesh: the same mesh on any number
  return request;
}

namespace {
mesh::TriangleMesh make_or_read_mesh(const Scenario& s, const std::optional<std::filesystem::path>& mesh_cache) {
  if (s.mesh->file) return read_mesh_file(s);
  const mesh::MeshRequest request = make_mesh_request(s);
  spdlog::info("mesh: {} expected", check_mesh_budget(s, request));
  if (!mesh_cache) return mesh::generate_mesh(request);
  mesh::CachedMesh cached = mesh::generate_or_reuse_mesh(request, *mesh_cache);
  for (const std::string& warning : cached.warnings) spdlog::warn("mesh: {}", warning);
  if (cached.reused || cached.stored)
    spdlog::info("mesh: {} {}", cached.reused ? "read from" : "made and stored in", cached.file.string());
  return std::move(cached.mesh);
}
}  // namespace

mesh::TriangleMesh build_mesh(const Scenario& s, const std::optional<std::filesystem::path>& mesh_cache) {
  mesh::TriangleMesh mesh = make_or_read_mesh(s, mesh_cache);
  mesh::order_spatially(mesh);  // whatever made it: the searches over its elements read memory in order
  return mesh;
}

// Triangles whose centroid lies in the polygon: the mesh honours region boundaries, so this is
// exact, and overlapping regions each keep all of their triangles.
std::vector<int> select_triangles_in(const mesh::TriangleMesh& mesh, const geometry::Polygon& polygon) {
  std::vector<int> out;
  for (int t = 0; t < mesh.triangle_count(); ++t)
    if (geometry::contains(polygon, mesh::triangle_centroid(mesh, t))) out.push_back(t);
  return out;
}

std::vector<std::optional<double>> find_imposed_permeability(const Scenario& s, const mesh::TriangleMesh& mesh) {
  std::vector<std::optional<double>> fixed(mesh.triangle_count());
  const auto& regions = s.flow->regions;
  for (auto r = regions.rbegin(); r != regions.rend(); ++r) {
    if (!r->permeability) continue;
    for (int t : select_triangles_in(mesh, r->polygon))
      if (!fixed[t]) fixed[t] = *r->permeability;
  }
  // A joint barrier's strip prevails over the regions: its elements are those of its mesh
  // region (joint_barriers.hpp).
  if (!s.any_joint_barrier()) return fixed;
  std::map<std::string, double> strip_permeability;
  for (const BarrierStrip& strip : find_barrier_strips(s)) strip_permeability[strip.region] = strip.permeability;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const int region = mesh.region[static_cast<std::size_t>(t)];
    const auto k = strip_permeability.find(mesh.region_names[static_cast<std::size_t>(region)]);
    if (k != strip_permeability.end()) fixed[t] = k->second;
  }
  return fixed;
}

std::vector<std::optional<double>> find_material_permeability(const Scenario& s, const mesh::TriangleMesh& mesh) {
  std::vector<std::optional<double>> fixed(mesh.triangle_count());
  const bool any_material_fixes = std::any_of(s.materials.begin(), s.materials.end(),
                                              [](const scenario::MaterialDefinition& m) { return m.permeability; });
  if (!any_material_fixes) return fixed;
  const std::vector<int> material = find_element_materials(s, mesh);
  for (std::size_t t = 0; t < fixed.size(); ++t)
    if (material[t] >= 0 && s.materials[material[t]].permeability) fixed[t] = *s.materials[material[t]].permeability;
  return fixed;
}

std::vector<std::optional<double>> find_fixed_permeability(const Scenario& s, const mesh::TriangleMesh& mesh) {
  std::vector<std::optional<double>> fixed = find_imposed_permeability(s, mesh);
  const std::vector<std::optional<double>> material = find_material_permeability(s, mesh);
  for (std::size_t t = 0; t < fixed.size(); ++t)
    if (!fixed[t]) fixed[t] = material[t];
  return fixed;
}

coupling::PermeabilityModel make_element_permeability_model(const Scenario& s, const mesh::TriangleMesh& mesh) {
  coupling::PermeabilityModel model = make_permeability_model(s);
  if (!scenario::has_material_regions(s)) return model;
  const std::vector<int> material = find_element_materials(s, mesh);
  for (int m : material) {
    const scenario::MaterialDefinition* own = m >= 0 ? &s.materials[m] : nullptr;
    model.element_matrix_porosity.push_back(own ? own->matrix_porosity : model.matrix_porosity);
    model.element_grain_diameter.push_back(own && own->grain_diameter ? *own->grain_diameter : model.grain_diameter);
  }
  return model;
}

std::vector<double> compute_matrix_permeability(const Scenario& s, const mesh::TriangleMesh& mesh) {
  const std::vector<std::optional<double>> fixed = find_fixed_permeability(s, mesh);
  // Only where some element is not fixed is a material needed.
  if (std::all_of(fixed.begin(), fixed.end(), [](const auto& k) { return k.has_value(); })) {
    std::vector<double> k;
    for (const auto& f : fixed) k.push_back(*f);
    return k;
  }
  const coupling::PermeabilityModel model = make_element_permeability_model(s, mesh);
  std::vector<double> k(fixed.size());
  for (std::size_t t = 0; t < fixed.size(); ++t) {
    if (fixed[t]) k[t] = *fixed[t];
    else if (model.element_matrix_porosity.empty()) k[t] = model.matrix_permeability();
    else k[t] = hydro::kozeny_carman_permeability(model.matrix_porosity_of(t), model.grain_diameter_of(t),
                                                  model.law == coupling::PermeabilityLaw::cubic
                                                      ? std::numeric_limits<double>::infinity() : model.cap);
  }
  return k;
}

hydro::DarcyProblem build_flow_problem(const scenario::FlowDefinition& f, double load_time) {
  hydro::DarcyProblem problem;
  problem.fluid.density = f.fluid_density;
  problem.fluid.viscosity = f.fluid_viscosity;
  problem.pressure = f.pressure;
  for (const scenario::FlowBoundaryCondition& bc : f.boundaries) problem.boundaries.push_back({bc.name, bc.kind, bc.value.value(load_time)});
  return problem;
}

double mechanics_duration(const scenario::MechanicsDefinition& m) {
  return m.end_time ? *m.end_time : m.time_step * static_cast<double>(m.steps.value_or(1));
}

namespace {

// The edge loads of every [[mechanics.traction]]; a boundary on which no block edge lies adds
// an error.
std::vector<dda::EdgeTraction> edge_tractions(const Scenario& s, const std::vector<dda::BlockDefinition>& blocks,
                                              std::vector<Diagnostic>& errors) {
  const double tolerance = geometric_tolerance(blocks);
  std::vector<dda::EdgeTraction> all;
  for (const scenario::Traction& t : s.mechanics->tractions) {
    const scenario::BoundarySegment* boundary = s.find_boundary(t.boundary);
    auto tractions = dda::make_tractions_on_segment(blocks, boundary->segment.from, boundary->segment.to, tolerance,
                                                    t.normal, t.normal_end, t.shear, t.shear_end);
    if (tractions.empty())
      errors.push_back({s.file.string(), t.line, "mechanics.traction.boundary",
                        fmt::format("no block edge lies on boundary \"{}\"", t.boundary)});
    all.insert(all.end(), tractions.begin(), tractions.end());
  }
  return all;
}

}  // namespace

std::vector<dda::EdgeTraction> build_tractions(const Scenario& scenario, const std::vector<dda::BlockDefinition>& blocks) {
  std::vector<Diagnostic> errors;
  std::vector<dda::EdgeTraction> tractions = edge_tractions(scenario, blocks, errors);
  if (!errors.empty()) throw scenario::ScenarioError(std::move(errors));
  return tractions;
}

dda::ModelDefinition build_mechanics_model(const Scenario& s, std::vector<dda::BlockDefinition> blocks) {
  const scenario::MechanicsDefinition& m = *s.mechanics;
  const std::string file = s.file.string();
  std::vector<Diagnostic> errors;
  const double tolerance = geometric_tolerance(blocks);
  const auto point_text = [](Point p) { return fmt::format("({:g}, {:g})", p.x, p.y); };

  dda::ModelDefinition model;
  for (const scenario::MaterialDefinition& mat : s.materials)
    model.materials.push_back({mat.density.value_or(0.0), mat.young.value_or(0.0), mat.poisson.value_or(0.0)});
  model.joint = {s.joint.friction_angle, s.joint.cohesion, s.joint.tensile_strength, s.joint.fracture_energy.value_or(0.0)};
  for (const scenario::JointDefinition& j : s.joint_types)
    model.joint_types.push_back({j.friction_angle, j.cohesion, j.tensile_strength, j.fracture_energy.value_or(0.0)});

  dda::Settings& settings = model.settings;
  settings.analysis = m.analysis;
  settings.plane = m.plane;
  settings.gravity = m.gravity;
  settings.time_step = m.time_step;
  if (m.max_displacement_ratio) {
    settings.max_displacement_ratio = *m.max_displacement_ratio;
  } else {
    const double usual = dda::Settings{}.max_displacement_ratio;
    settings.max_displacement_ratio = dda::displacement_ratio_for_blocks(blocks, usual);
    if (settings.max_displacement_ratio < usual)
      spdlog::debug("default used: mechanics.max_displacement_ratio = {:.3g} (below {:g}: the contact distance, {:.3g} m, "
                    "is half the thinnest block's width)",
                    settings.max_displacement_ratio, usual, dda::initial_contact_distance(blocks, settings));
    else
      spdlog::debug("default used: mechanics.max_displacement_ratio = {:g}", usual);
  }
  settings.contact = m.contact;
  settings.penalty = m.penalty.value_or(0.0);
  settings.tension_cutoff = m.tension_cutoff;
  if (m.penetration_tolerance) {
    settings.penetration_tolerance = *m.penetration_tolerance;
  } else if (const double a0 = smallest_joint_zero_stress_aperture(s); s.any_joint_hydraulic() && a0 > 0.0) {
    // Joints that conduct while closed read their aperture from the gap where it exceeds the
    // penetration tolerance, and from the contact stress below it: a gap within the tolerance
    // counts as closed. The DDA's own resolution, 1e-4 of the allowed step displacement (15 µm
    // for a model 30 m high), would blur the micrometres the flow sees; at a fiftieth of
    // a_r + V_m, halving the tolerance moves a seal's K_eff by 0.1% at most (docs/coupling.md,
    // "Joint hydraulic apertures").
    const double usual = dda::initial_penetration_tolerance(blocks, settings);
    const double resolved = kJointApertureResolution * a0;
    if (resolved < usual) {
      settings.penetration_tolerance = resolved;
      spdlog::debug("default used: mechanics.penetration_tolerance = {:.3g} m ({:g} of the joint types' smallest a_r + V_m; "
                    "1e-4 of the allowed step displacement would be {:.3g} m)",
                    resolved, kJointApertureResolution, usual);
    }
  }

  const double run_duration = mechanics_duration(m);
  for (const scenario::FixedPoint& f : m.fixed) {
    const int block = find_block(blocks, f.point, tolerance);
    if (block < 0) errors.push_back({file, f.line, "mechanics.fixed.point", fmt::format("{} lies in no block", point_text(f.point))});
    else model.fixed_points.push_back({block, f.point});
  }
  for (const scenario::PointLoad& l : m.loads) {
    const int block = find_block(blocks, l.point, tolerance);
    if (block < 0) errors.push_back({file, l.line, "mechanics.load.point", fmt::format("{} lies in no block", point_text(l.point))});
    else model.point_loads.push_back({block, l.point, l.force});
  }
  for (std::size_t entry = 0; entry < m.displacements.size(); ++entry) {
    const scenario::PrescribedDisplacement& d = m.displacements[entry];
    const int e = static_cast<int>(entry);
    if (d.point) {
      const int block = find_block(blocks, *d.point, tolerance);
      if (block < 0) errors.push_back({file, d.line, "mechanics.displacement.point", fmt::format("{} lies in no block", point_text(*d.point))});
      else model.displacements.push_back({block, *d.point, d.value, d.ramp_time.value_or(run_duration), e});
      continue;
    }
    const scenario::BoundarySegment* boundary = s.find_boundary(d.boundary);
    const auto vertices = dda::select_vertices_on_segment(blocks, boundary->segment.from, boundary->segment.to, tolerance);
    if (vertices.empty())
      errors.push_back({file, d.line, "mechanics.displacement.boundary", fmt::format("no block vertex lies on boundary \"{}\"", d.boundary)});
    for (const dda::VertexRef& v : vertices)
      model.displacements.push_back(
          {v.block, blocks[v.block].polygon[v.vertex], d.value, d.ramp_time.value_or(run_duration), e});
  }
  model.tractions = edge_tractions(s, blocks, errors);
  if (m.initial_stress) {
    model.initial_stress = build_initial_stress(s);
    if (!m.initial_stress->layers) note_unbalanced_initial_stress(s);
    const auto mismatches = compare_in_situ_stress(s, blocks, *model.initial_stress);
    if (const std::optional<std::string> warning = describe_in_situ_mismatch(s, mismatches)) spdlog::warn("{}", *warning);
  }
  for (const scenario::RollerDefinition& r : m.rollers) {
    const scenario::BoundarySegment* boundary = s.find_boundary(r.boundary);
    const auto rollers = dda::make_rollers_on_segment(blocks, boundary->segment.from, boundary->segment.to, tolerance,
                                                      model.initial_stress);
    if (rollers.empty())
      errors.push_back({file, r.line, "mechanics.roller.boundary", fmt::format("no block vertex lies on boundary \"{}\"", r.boundary)});
    model.rollers.insert(model.rollers.end(), rollers.begin(), rollers.end());
  }
  for (const scenario::MeasurePoint& p : m.measures) {
    const int block = find_block(blocks, p.point, tolerance);
    if (block < 0) errors.push_back({file, p.line, "mechanics.measure.point", fmt::format("{} lies in no block", point_text(p.point))});
    else model.measured_points.push_back({block, p.point});
  }
  model.broken_bonds = find_crack_bonds(s, blocks);  // a tessellation's cracks start broken
  if (!model.broken_bonds.empty()) spdlog::info("geometry: {} bonds start broken along the cracks", model.broken_bonds.size());
  model.blocks = std::move(blocks);
  // Only on supports that all resolved: one in no block is its own error, not a missing support.
  if (errors.empty() && settings.analysis == dda::Analysis::static_) report_unsupported_blocks(s, model, errors);
  if (!errors.empty()) throw scenario::ScenarioError(std::move(errors));
  return model;
}

}  // namespace hydrodda::run
