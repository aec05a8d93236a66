#include "run/coupled_model.hpp"

#include "scenario/load_times.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "run/model_building.hpp"
#include "run/model_geometry.hpp"
#include "run/run_summary.hpp"
#include "run/sub_blocks.hpp"
#include "run/transient_flow.hpp"

namespace hydrodda::run {

namespace {
using Clock = std::chrono::steady_clock;

// A material's drained bulk modulus in the plane (0 without elastic constants): E/(2(1 + ν)(1 − 2ν))
// in plane strain (λ + μ: tr σ = 2 K_dr ε_v), E/(2(1 − ν)) in plane stress.
double drained_bulk_modulus(const scenario::MaterialDefinition& material, bool plane_strain) {
  const double young = material.young.value_or(0.0), nu = material.poisson.value_or(0.0);
  return plane_strain ? young / (2.0 * (1.0 + nu) * (1.0 - 2.0 * nu)) : young / (2.0 * (1.0 - nu));
}

// The fixed-stress split's matrix storage per element (1/Pa): its material's 1/M (`storage`)
// plus α²/K_dr, K_dr the drained bulk modulus in the plane, E/(2(1 + ν)(1 − 2ν)) in plane
// strain and E/(2(1 − ν)) in plane stress (Kim, Tchelepi & Juanes 2011).
coupling::PseudoTimeSettings make_pseudo_time_settings(const scenario::Scenario& s, const mesh::TriangleMesh& mesh) {
  coupling::PseudoTimeSettings pseudo;
  pseudo.first_step = s.coupling.pseudo_time_step;
  pseudo.fluid_compressibility = s.flow->fluid_compressibility;
  pseudo.unit_weight = s.flow->fluid_density * hydro::Fluid{}.gravity;
  const bool strain = s.mechanics->plane == dda::Plane::strain;
  for (int m : find_element_materials(s, mesh)) {
    const scenario::MaterialDefinition& material = s.materials[m >= 0 ? m : 0];
    const double bulk = drained_bulk_modulus(material, strain);
    const double alpha = material.biot_coefficient;
    pseudo.matrix_storage.push_back(material.storage + (bulk > 0.0 ? alpha * alpha / bulk : 0.0));
  }
  return pseudo;
}
// The fixed-stress split's materials, per block (coupling/fixed_stress_step.hpp): the storage
// 1/M, Biot's α and the drained bulk modulus in the plane, E/(2(1 + ν)(1 − 2ν)) in plane strain
// (λ + μ: the 2D bulk modulus, tr σ = 2 K_dr ε_v) and E/(2(1 − ν)) in plane stress.
coupling::FixedStressSettings make_fixed_stress_settings(const scenario::Scenario& s,
                                                         const std::vector<dda::BlockDefinition>& blocks) {
  coupling::FixedStressSettings fixed;
  fixed.fluid_compressibility = s.flow->fluid_compressibility;
  fixed.unit_weight = s.flow->fluid_density * hydro::Fluid{}.gravity;
  const bool strain = s.mechanics->plane == dda::Plane::strain;
  for (const dda::BlockDefinition& b : blocks) {
    const scenario::MaterialDefinition& material = s.materials[b.material];
    fixed.storage.push_back(material.storage);
    fixed.biot.push_back(material.biot_coefficient);
    fixed.drained_bulk.push_back(drained_bulk_modulus(material, strain));
  }
  return fixed;
}

bool has_tessellation(const scenario::Scenario& s) { return s.geometry && !s.geometry->tessellations.empty(); }

// The joints the flow sees as embedded fractures: the traces', each by its type's hydraulic
// aperture law, and with bonded sub-blocks every bond's face too (by its bonds' type), which
// conducts once broken (run/sub_blocks.hpp, network_with_bond_faces).
coupling::LoopSettings::Joints make_embedded_joints(const scenario::Scenario& s) {
  ModelGeometry geometry = build_model_geometry(s);
  if (geometry.bond_types.empty())
    return {std::move(geometry.network), make_joint_aperture_laws(s, geometry.traces)};
  geometry::BlockNetwork network = network_with_bond_faces(geometry);
  const int first_bond = static_cast<int>(geometry.traces.size());
  std::vector<geometry::FractureTrace> fractures = geometry.traces;  // by fracture id: the traces, then the bonds
  for (int type : geometry.bond_types) fractures.push_back({{}, {}, type});
  return {std::move(network), make_joint_aperture_laws(s, fractures), first_bond};
}
}  // namespace

CoupledModel::CoupledModel(const scenario::Scenario& scenario, const std::optional<std::filesystem::path>& mesh_cache,
                           std::span<const scenario::MeshRefinePoint> added_refinement)
    : scenario_(scenario) {
  std::vector<scenario::MeshRefinePoint>& refine = scenario_.mesh->refine_points;
  refine.insert(refine.end(), added_refinement.begin(), added_refinement.end());
  const scenario::Scenario& s = scenario_;
  const auto start = Clock::now();
  mesh_ = build_mesh(s, mesh_cache);
  mesh_seconds_ = std::chrono::duration<double>(Clock::now() - start).count();
  spdlog::info("mesh: {} nodes, {} triangles", mesh_.node_count(), mesh_.triangle_count());

  // A later round of mesh.refine_tips (refinement added) cuts the blocks its first round cut.
  std::vector<dda::BlockDefinition> block_definitions =
      build_blocks(s, added_refinement.empty() ? GeometryWarnings::logged : GeometryWarnings::already_logged);
  coupling::LoopSettings settings;
  settings.biot_coefficients = find_biot_coefficients(s, block_definitions);
  if (s.flow->transient) settings.fixed_stress = make_fixed_stress_settings(s, block_definitions);
  initial_blocks_ = block_definitions;
  system_.emplace(build_mechanics_model(s, std::move(block_definitions)));
  spdlog::info("mechanics: {} blocks", system_->block_count());

  settings.tolerance = s.coupling.tolerance;
  settings.relaxation = s.coupling.relaxation;
  settings.acceleration = s.coupling.acceleration;
  // In time the loads come with the steps: no ramp over a step's iterations.
  settings.ramp_passes = s.flow->transient ? 1 : s.coupling.ramp_passes;
  settings.ramp_if_moved = s.flow->transient ? 0 : s.coupling.ramp_if_moved;
  settings.ramped_load = s.coupling.ramp;
  settings.steps_per_pass = s.mechanics->steps.value_or(
      static_cast<int>(std::ceil(*s.mechanics->end_time / s.mechanics->time_step)));
  // At most a hundred times the pass's own steps (and no more than a run's): the up-down
  // six-block model's first pass needed 26 times its 100 (docs/coupling.md, "Passes that settle").
  settings.settle_steps =
      s.coupling.settle ? static_cast<int>(std::min<long long>(100LL * settings.steps_per_pass, scenario::kMaxSteps)) : 0;
  settings.permeability = make_element_permeability_model(s, mesh_);
  // Left empty where no region, material or joint barrier fixes a permeability: one optional per
  // element is 16 MB at a million triangles.
  if (s.any_joint_barrier() || std::any_of(s.flow->regions.begin(), s.flow->regions.end(),
                                           [](const scenario::FlowRegion& r) { return r.permeability.has_value(); }))
    settings.fixed_permeability = find_imposed_permeability(s, mesh_);
  if (std::any_of(s.materials.begin(), s.materials.end(),
                  [](const scenario::MaterialDefinition& m) { return m.permeability.has_value(); }))
    settings.material_permeability = find_material_permeability(s, mesh_);
  if (s.any_joint_hydraulic() || has_tessellation(s)) settings.joints = make_embedded_joints(s);
  if (s.coupling.pseudo_time_step > 0.0) settings.pseudo_time = make_pseudo_time_settings(s, mesh_);
  settings.stop_requested = [this] { return stop_requested_ && stop_requested_(); };
  // Within a DDA step too, between its open–close passes: the loop abandons the pass.
  system_->set_interrupt_check([this] { return stop_requested_ && stop_requested_(); });
  load_times_ = scenario::find_load_times(s);
  loop_.emplace(mesh_, build_flow_problem(*s.flow, load_time()), *system_, std::move(settings));
  if (has_load_tables()) system_->hold_load_time(load_time());
  // The unfractured case does not change between passes: solved once (and again for a load
  // step's new boundary values).
  region_references_ = reference_regions(s, mesh_, load_time());
}

void CoupledModel::set_flow_boundaries(std::vector<scenario::FlowBoundaryCondition> boundaries) {
  scenario::Scenario changed = scenario_;
  changed.flow->boundaries = std::move(boundaries);
  loop_->set_flow_boundary_values(build_flow_problem(*changed.flow, load_time()).boundaries);
  scenario_ = std::move(changed);
  region_references_ = reference_regions(scenario_, mesh_, load_time());
}

void CoupledModel::start_load_step(int step) {
  if (step < 1 || step > load_steps()) throw std::invalid_argument("CoupledModel: no load step " + std::to_string(step));
  load_step_ = step;
  if (!has_load_tables()) return;
  loop_->set_flow_boundary_values(build_flow_problem(*scenario_.flow, load_time()).boundaries);
  system_->hold_load_time(load_time());
  region_references_ = reference_regions(scenario_, mesh_, load_time());
}

void CoupledModel::start_in_time() {
  if (!transient()) throw std::logic_error("CoupledModel: start_in_time() without [flow.transient]");
  const std::optional<double> head = scenario_.flow->transient->initial_head;
  if (!head) {
    loop_->start_in_time(std::nullopt);
    return;
  }
  const hydro::DarcyProblem problem = build_flow_problem(*scenario_.flow, 0.0);
  loop_->start_in_time(make_uniform_state(mesh_, problem, loop_->flow_reference_head(), *head));
}

void CoupledModel::begin_time_step(double time, double time_step) {
  const double end = time + time_step;
  loop_->set_flow_boundary_values(build_flow_problem(*scenario_.flow, end).boundaries);
  system_->hold_load_time(end);
  loop_->begin_time_step(time_step);
}

void CoupledModel::begin_steady_at(double time) {
  loop_->set_flow_boundary_values(build_flow_problem(*scenario_.flow, time).boundaries);
  system_->hold_load_time(time);
  loop_->leave_time_step();
}

void CoupledModel::set_tractions(std::vector<scenario::Traction> tractions) {
  scenario::Scenario changed = scenario_;
  changed.mechanics->tractions = std::move(tractions);
  system_->set_tractions(build_tractions(changed, initial_blocks_));
  loop_->begin_new_load();
  scenario_ = std::move(changed);
}

void CoupledModel::import_state(const CoupledState& state) { loop_->import_state(state.coupling, state.mechanics); }

std::vector<geometry::Polygon> CoupledModel::block_polygons() const {
  std::vector<geometry::Polygon> blocks;
  for (int b = 0; b < system_->block_count(); ++b) blocks.push_back(system_->polygon(b));
  return blocks;
}

output::RunSummary CoupledModel::summary() const {
  output::RunSummary summary = summarise_mechanics(scenario_, *system_);
  if (loop_->has_flow()) {
    summary.flow = summarise_flow(scenario_, mesh_, loop_->flow(), region_references_,
                                  loop_->permeability_tensors().empty()
                                      ? hydro::PermeabilityView(loop_->permeability())
                                      : hydro::PermeabilityView(loop_->permeability_tensors()));
    summary.flow->iteration = loop_->iterations();
    const coupling::MeshExcursion outside = loop_->outside_mesh();
    summary.outside_mesh = output::OutsideMeshSummary{outside.distance, outside.block, outside.blocks_outside};
  }
  summary.iterations = loop_->iterations();
  return summary;
}

std::vector<std::optional<output::RegionSummary>> CoupledModel::region_flows() const {
  return summarise_regions(scenario_, mesh_, loop_->flow(), region_references_, {});
}

std::vector<output::NamedValue> CoupledModel::timings() const {
  const coupling::StaggeredLoop::PhaseSeconds& passes = loop_->phase_seconds();
  return {{"mesh", mesh_seconds_}, {"porosity", passes.porosity}, {"flow", passes.flow},
          {"forces", passes.forces}, {"mechanics", passes.mechanics}};
}

}  // namespace hydrodda::run
