#include "coupling/staggered_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "coupling/local_aperture.hpp"
#include "coupling/pass_changes.hpp"
#include "coupling/settling_watch.hpp"
#include "hydro/element_pressure.hpp"
#include "numerics/aitken.hpp"

namespace hydrodda::coupling {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void check_finite(const std::vector<double>& values, const char* what, int iteration) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw std::runtime_error(std::string(what) + " is not finite at index " + std::to_string(i) +
                               " in coupling iteration " + std::to_string(iteration));
}
}  // namespace

void ChangeGrowth::add(double change, int iteration, int ramp_passes) {
  // Pass k's change compares it with pass k − 1, at the full load from pass ramp_passes on.
  if (iteration > std::max(2, ramp_passes + 1) && change > last) {
    if (passes == 0) base = last;
    ++passes;
  } else {
    passes = 0;
  }
  last = change;
}

double displacement_change(const std::vector<Point>& current, const std::vector<Point>& previous,
                           double reference_length) {
  double moved = 0.0, largest = 0.0;
  for (std::size_t b = 0; b < current.size(); ++b) {
    const Point before = b < previous.size() ? previous[b] : Point{0.0, 0.0};
    moved = std::max(moved, std::hypot(current[b].x - before.x, current[b].y - before.y));
    largest = std::max(largest, std::hypot(current[b].x, current[b].y));
  }
  if (moved == 0.0) return 0.0;
  const double scale = std::max(largest, reference_length);
  return scale > 0.0 ? moved / scale : 1.0;
}

double head_change(const std::vector<double>& current, const std::vector<double>& previous) {
  if (current.empty()) return 0.0;
  double diff = 0.0, low = current[0], high = current[0];
  for (std::size_t i = 0; i < current.size(); ++i) {
    const double d = current[i] - (i < previous.size() ? previous[i] : 0.0);
    diff += d * d;
    low = std::min(low, current[i]);
    high = std::max(high, current[i]);
  }
  if (diff == 0.0) return 0.0;
  if (high == low) return 1.0;
  return std::sqrt(diff / static_cast<double>(current.size())) / (high - low);
}

StaggeredLoop::StaggeredLoop(const mesh::TriangleMesh& mesh, hydro::DarcyProblem flow, dda::System& mechanics,
                             LoopSettings settings)
    : mesh_(mesh),
      mechanics_(mechanics),
      settings_(std::move(settings)),
      darcy_(mesh, std::move(flow)),
      elements_(std::make_shared<const ElementIndex>(mesh.nodes, mesh.triangles)),
      porosity_mapper_(elements_),
      boundary_gaps_(elements_, settings_.permeability.domain, current_blocks()),
      face_loads_(mesh, elements_),
      anderson_(settings_.anderson_depth) {
  for (int b = 0; b < mechanics.block_count(); ++b) block_sizes_.push_back(std::sqrt(mechanics.area(b)));
  if (!settings_.fixed_permeability.empty() &&
      settings_.fixed_permeability.size() != static_cast<std::size_t>(mesh.triangle_count()))
    throw std::invalid_argument("coupling: one fixed-permeability entry per element is needed");
  std::vector<double>& biot = settings_.biot_coefficients;
  if (biot.empty()) biot.assign(mechanics.block_count(), 1.0);
  if (biot.size() != static_cast<std::size_t>(mechanics.block_count()))
    throw std::invalid_argument("coupling: one Biot coefficient per block is needed");
  if (!(settings_.relaxation > 0.0 && settings_.relaxation <= 1.0))
    throw std::invalid_argument("coupling: the relaxation must lie in (0, 1]");
  if (settings_.anderson_depth < 1) throw std::invalid_argument("coupling: the Anderson depth must be at least 1");
  if (settings_.ramp_passes < 1) throw std::invalid_argument("coupling: ramp_passes must be at least 1");
  relaxation_ = settings_.relaxation;
  if (settings_.joints)
    joints_.emplace(mesh, std::move(settings_.joints->network), std::move(settings_.joints->laws),
                    settings_.joints->first_bond_fracture);
  for (double alpha : biot) {
    if (!(alpha >= 0.0 && alpha <= 1.0)) throw std::invalid_argument("coupling: a Biot coefficient must lie in [0, 1]");
    seepage_ = seepage_ || alpha > 0.0;
  }
  last_mechanics_ = mechanics_.export_state();
}

std::vector<geometry::Polygon> StaggeredLoop::current_blocks() const {
  std::vector<geometry::Polygon> blocks;
  blocks.reserve(mechanics_.block_count());
  for (int b = 0; b < mechanics_.block_count(); ++b) blocks.push_back(mechanics_.polygon(b));
  return blocks;
}

std::vector<char> StaggeredLoop::broken_bonds() const {
  std::vector<char> broken(static_cast<std::size_t>(mechanics_.bond_count()));
  for (int bond = 0; bond < mechanics_.bond_count(); ++bond) broken[static_cast<std::size_t>(bond)] = mechanics_.is_bond_broken(bond);
  return broken;
}

// An intact bond is rock: the fluid stands on neither of its faces. Loading both with (1 − α) p
// would cancel in their sum but press each sub-block as though water filled the face, the
// tessellated rock then taking the whole pore pressure (α = 1) sub-block by sub-block whatever
// its α; unloaded, the sub-blocks together take the loads of the block they tessellate
// (−α ∇p inside, (1 − α) p on its faces), and an intact bond's contacts carry the effective
// traction σ' n = (σ + α p I) n of its sub-blocks' stress, the one that breaks it.
std::vector<std::vector<char>> StaggeredLoop::sealed_edges() const {
  std::vector<std::vector<char>> sealed;
  if (mechanics_.bond_count() == 0) return sealed;
  sealed.resize(static_cast<std::size_t>(mechanics_.block_count()));
  for (int b = 0; b < mechanics_.block_count(); ++b) {
    const std::size_t n = mechanics_.polygon(b).size();
    std::vector<char>& edges = sealed[static_cast<std::size_t>(b)];
    for (std::size_t e = 0; e < n; ++e) {
      const int bond = mechanics_.bond_of_edge(b, static_cast<int>(e));
      if (bond >= 0 && !mechanics_.is_bond_broken(bond)) {
        edges.resize(n, 0);
        edges[e] = 1;
      }
    }
  }
  return sealed;
}

std::vector<double> StaggeredLoop::compute_joint_apertures(std::span<const geometry::Polygon> blocks) const {
  return joints_->apertures(blocks, mechanics_.contacts(), mechanics_.penetration_tolerance(), broken_bonds());
}

// The permeability as the porosity law gives it (a material's own `permeability` in its stead),
// the scenario's imposed values over it; with joints, the elements along them at the matrix
// permeability in series with their open fraction, plus the joints' transmissivity (one
// transmissivity per joint: embedded_joints.hpp), solved as tensors.
hydro::FlowSolution StaggeredLoop::solve_flow(const std::vector<geometry::Polygon>& blocks) {
  const hydro::PermeabilityView k = update_permeability(blocks);
  if (time_level_) return step_in_time(k);
  return darcy_.solve_reusing_factor(k, solution_.head);
}

hydro::PermeabilityView StaggeredLoop::update_permeability(const std::vector<geometry::Polygon>& blocks) {
  const auto given = [](const std::vector<std::optional<double>>& k, std::size_t e) {
    return e < k.size() && k[e].has_value();
  };
  for (std::size_t e = 0; e < permeability_.size(); ++e)
    if (given(settings_.material_permeability, e)) permeability_[e] = *settings_.material_permeability[e];
  if (!joints_) {
    for (std::size_t e = 0; e < permeability_.size(); ++e)
      if (given(settings_.fixed_permeability, e)) permeability_[e] = *settings_.fixed_permeability[e];
    check_finite(permeability_, "the permeability", iteration_);
    return hydro::PermeabilityView(permeability_);
  }
  set_joint_zone_matrix_permeability();
  joint_apertures_ = compute_joint_apertures(blocks);
  check_finite(joint_apertures_, "a joint's hydraulic aperture", iteration_);
  std::vector<hydro::PermeabilityTensor>& k = permeability_tensors_;
  k = joints_->permeability(permeability_, joint_apertures_);
  for (std::size_t e = 0; e < k.size(); ++e) {
    if (given(settings_.fixed_permeability, e))
      k[e] = {*settings_.fixed_permeability[e], 0.0, *settings_.fixed_permeability[e]};
    permeability_[e] = largest_principal_value(k[e]);
  }
  check_finite(permeability_, "the permeability", iteration_);
  return hydro::PermeabilityView(k);
}

// The elements along the joints take the matrix permeability (their material's), not the
// porosity law's, which would count an open joint a second time; but in series with the
// element's open fraction, so that a gap opened as wide as the element does not hold back the
// flow across it as rock would (a seal lifted off its base).
void StaggeredLoop::set_joint_zone_matrix_permeability() {
  const double k_matrix = settings_.permeability.matrix_permeability();
  const bool by_element = settings_.permeability.by_element();  // materials by region
  const std::span<const double> areas = porosity_mapper_.element_areas();
  for (std::size_t e = 0; e < permeability_.size(); ++e) {
    if (!joints_->zone()[e]) continue;
    const bool own = e < settings_.material_permeability.size() && settings_.material_permeability[e];
    const double k_m = own ? *settings_.material_permeability[e]
                           : (by_element ? settings_.permeability.matrix_permeability_of(e) : k_matrix);
    const double open_fraction = porosity_.fracture_area[e] / areas[e];
    permeability_[e] = hydro::permeability_across_open_fraction(k_m, open_fraction, settings_.permeability.fracture_cap);
  }
}

std::vector<EscapingBlock> StaggeredLoop::blocks_beyond_their_size() const {
  std::vector<EscapingBlock> beyond;
  for (int b = 0; b < mechanics_.block_count(); ++b) {
    const Point u = mechanics_.displacement(b);
    const double distance = std::hypot(u.x, u.y);
    if (distance > block_sizes_[b]) beyond.push_back({b, distance, block_sizes_[b]});
  }
  std::sort(beyond.begin(), beyond.end(),
            [](const EscapingBlock& a, const EscapingBlock& b) { return a.distance > b.distance; });
  return beyond;
}

std::vector<Point> StaggeredLoop::block_displacements() const {
  std::vector<Point> u;
  for (int b = 0; b < mechanics_.block_count(); ++b) u.push_back(mechanics_.displacement(b));
  return u;
}

// The fluid forces of the P1 pressure field `pressure` on the blocks as they are now: the faces'
// share (1 − α) of the pressure along them, and the seepage force −α ∇p inside (on the pieces
// of this pass's clip).
std::vector<std::vector<Point>> StaggeredLoop::fluid_forces(const std::vector<geometry::Polygon>& blocks,
                                                            std::span<const double> pressure) const {
  std::vector<std::vector<Point>> forces =
      face_loads_.compute(blocks, pressure, settings_.biot_coefficients, sealed_edges());
  if (!seepage_) return forces;
  const std::vector<std::vector<Point>> seepage = compute_seepage_forces(
      blocks, pieces_, hydro::compute_pressure_gradients(mesh_, pressure), settings_.biot_coefficients);
  for (std::size_t b = 0; b < forces.size(); ++b)
    for (std::size_t v = 0; v < forces[b].size(); ++v) forces[b][v] += seepage[b][v];
  return forces;
}

PassReport StaggeredLoop::run_pass() {
  PassReport report;
  report.iteration = ++iteration_;
  // The contacts as the last pass left them, to count which this one changes.
  const std::vector<dda::ContactInfo> contacts_before = mechanics_.contacts();
  pass_start_.emplace();
  pass_start_->kept_factor = darcy_.kept_factor();
  pass_start_->kept_factor_single_precision = darcy_.kept_factor_in_single_precision();
  pass_start_->pseudo_time_step = pseudo_time_step_;
  pass_start_->last_steady_change = last_steady_change_;
  if (time_level_) {
    pass_start_->step_passes = time_level_->passes++;
    pass_start_->step_gaps = time_level_->gaps;
  }

  // Porosity and permeability from the blocks as they are now: recomputed every pass.
  auto start = Clock::now();
  const std::vector<geometry::Polygon> blocks = current_blocks();
  // The last pass's fields set aside, given back if this pass fails or is stopped.
  pass_start_->porosity = std::exchange(porosity_, {});
  pass_start_->permeability = std::exchange(permeability_, {});
  pass_start_->permeability_tensors = std::exchange(permeability_tensors_, {});
  pass_start_->joint_apertures = std::exchange(joint_apertures_, {});
  // The pieces for the seepage force, and for the skeleton's volumes of a time step.
  porosity_ = clip_blocks(blocks, seepage_ || settings_.fixed_stress ? &pieces_ : nullptr);
  std::vector<double> apertures;
  if (settings_.permeability.reads_apertures())
    apertures = compute_local_apertures(mesh_, porosity_.fracture_area, blocks, settings_.permeability.domain,
                                        settings_.permeability.aperture_reach);
  permeability_ = settings_.permeability.compute(porosity_, porosity_mapper_.element_areas(), apertures);
  capped_elements_ = settings_.permeability.find_capped_elements(porosity_, porosity_mapper_.element_areas(), apertures);
  // Along the joints the porosity law's value gives way to the matrix's and the joints' own
  // transmissivity (set_joint_zone_matrix_permeability): no cap of w²/12 acts there.
  if (joints_) std::erase_if(capped_elements_, [&](int e) { return joints_->zone()[e] != 0; });
  report.porosity_seconds = seconds_since(start);

  // Flow, with the heads under-relaxed against the last pass. The permeability changes little
  // from pass to pass: the factor of an earlier pass serves as CG's preconditioner from the
  // last heads while it converges fast (hydro::DarcySolver::solve_reusing_factor).
  start = Clock::now();
  hydro::FlowSolution fresh = solve_flow(blocks);
  check_finite(fresh.head, "the head", iteration_);
  // Judged on the fresh (unrelaxed) heads: the relaxed change is ω times this, so a small ω
  // would freeze the heads and fake convergence.
  const double unrelaxed_head_change = previous_heads_.empty() ? 1.0 : head_change(fresh.head, previous_heads_);
  if (settings_.pseudo_time && !time_level_ && !previous_heads_.empty()) {
    fresh = step_in_pseudo_time(unrelaxed_head_change);
    check_finite(fresh.head, "the head", iteration_);
  }
  pass_start_->previous_update = previous_update_;
  pass_start_->relaxation = relaxation_;
  if (settings_.acceleration == Acceleration::anderson) pass_start_->anderson_history = anderson_.history();
  relax(fresh);
  report.relaxation = previous_heads_.empty() ? 1.0 : relaxation_;
  pass_start_->solution = std::exchange(solution_, std::move(fresh));
  pass_start_->flow_solved = true;
  report.flow_seconds = seconds_since(start);

  // The P1 pressure field to forces on the blocks as they are now: the faces' share (1 − α)
  // of the pressure along them, and the seepage force −α ∇p inside.
  start = Clock::now();
  // Ramped over the first passes: the blocks meet the full load from a state near equilibrium
  // under part of it, instead of all at once from the state as built (load_ramp.hpp).
  report.load_factor = ramp_factor(iteration_, settings_.ramp_passes);
  const bool from_still_water = report.load_factor < 1.0 && settings_.ramped_load == RampedLoad::overpressure;
  const std::vector<double> still_pressure = from_still_water ? darcy_.still_water_pressure() : std::vector<double>{};
  std::vector<std::vector<Point>> forces = fluid_forces(blocks, solution_.pressure);
  if (from_still_water) ramp_fluid_forces(forces, fluid_forces(blocks, still_pressure), report.load_factor);
  else ramp_fluid_forces(forces, {}, report.load_factor);
  // Made again by the next pass's clip: not held while the blocks move.
  if (seepage_) pieces_.release();
  report.fluid_load_change = relative_load_change(forces, last_mechanics_.vertex_forces);
  mechanics_.set_vertex_forces(std::move(forces));
  // A run that starts in its in-situ stress: the faces take their share (1 − α) p of the first
  // pass's pressure, which the contacts and rollers then need not carry, so that they start in
  // the effective traction (σ + p I) n while the blocks carry σ + α p I. The pressure is the
  // ramped load's: r p, or p_s + r (p − p_s).
  if (iteration_ == 1 && std::any_of(settings_.biot_coefficients.begin(), settings_.biot_coefficients.end(),
                                     [](double alpha) { return alpha < 1.0; }))
    mechanics_.relieve_start_loads([&, factor = report.load_factor](int block, Point from, Point to) {
      const auto integral = [&](std::span<const double> pressure) {
        const FacePressureLoads::SegmentIntegrals along = face_loads_.integrate_along(from, to, pressure);
        return along.start_inside + along.start_outside;
      };
      const double face_share = 1.0 - settings_.biot_coefficients[static_cast<std::size_t>(block)];
      const double full = integral(solution_.pressure);
      if (!from_still_water) return factor * face_share * full;
      const double still = integral(still_pressure);
      // Written so that still water loading nothing (p_s = 0) gives the whole ramp's bits.
      return face_share * still + factor * face_share * (full - still);
    });
  report.forces_seconds = seconds_since(start);

  const std::vector<Point> start_displacements = block_displacements();
  step_mechanics(report);
  if (settings_.ramp_if_moved > 1 && settings_.ramp_passes == 1 && iteration_ == 1)
    if (const std::optional<double> moved = ramp_if_the_load_moved()) return run_pass_ramped(*moved);
  move_free_groups(report, start_displacements);
  report.contact_state_changes = count_contact_state_changes(contacts_before, mechanics_.contacts());
  if (joints_)
    report.joint_crossings_switched =
        count_switched(joint_apertures_, compute_joint_apertures(current_blocks()), joints_->zero_stress_apertures());
  measure_convergence(report, unrelaxed_head_change);
  finish_pass(report);
  return report;
}

// The first pass of a model that starts in an in-situ stress, its load put on at once: where
// the blocks stood in equilibrium with the whole load (an in-situ stress balancing the steady
// seepage) they stay put and the run goes on as it is. Where they moved by more than the
// tolerance's share of the allowed step displacement (as a converged pass may not), the in-situ
// stress stood with still water, and the whole load at once throws the
// blocks past the state a slow rise leaves them in, where friction then keeps them (docs/
// coupling.md, "Relaxation, acceleration and the load ramp"): the pass is undone and the load
// ramped over settings_.ramp_if_moved passes, and how far the blocks moved returned for the
// caller to run the pass again with; none: the run goes on at once.
std::optional<double> StaggeredLoop::ramp_if_the_load_moved() {
  double largest = 0.0;
  for (int b = 0; b < mechanics_.block_count(); ++b) {
    const Point u = mechanics_.displacement(b);
    largest = std::max(largest, std::hypot(u.x, u.y));
  }
  const int ramp = std::exchange(settings_.ramp_if_moved, 0);  // chosen once
  if (largest <= settings_.tolerance * mechanics_.allowed_step_displacement()) return std::nullopt;
  abandon_pass();
  settings_.ramp_passes = ramp;
  return largest;
}

// The first pass again, ramped, its report saying why (PassReport::moved_at_once).
PassReport StaggeredLoop::run_pass_ramped(double moved_at_once) {
  PassReport report = run_pass();
  report.moved_at_once = moved_at_once;
  return report;
}

// Mechanics under the mechanical and fluid loads: the pass's steps, then (settle_steps) on
// until the blocks are at rest, as its fixed steps may stop them part-way to the equilibrium
// of its loads and the next pass would meet them there (docs/coupling.md, "Passes that
// settle"). Settling stops sooner, the blocks not at rest, once steps_per_pass steps in a row
// have each moved a block freely that cannot come to rest within the steps left
// (SettlingWatch): a stack of blocks falling into open joints lands a row at a time, hundreds
// of steps a row, and a pass that stepped on to its limit would cost a hundred fixed passes
// and still end moving.
void StaggeredLoop::step_mechanics(PassReport& report) {
  const auto start = Clock::now();
  const int most_steps = settings_.steps_per_pass + settings_.settle_steps;
  int taken = 0;
  SettlingWatch watch(settings_.steps_per_pass, mechanics_.at_rest_displacement());
  bool at_rest = false;
  report.shortest_time_step = mechanics_.full_time_step();
  pass_squared_steps_ = 0.0;
  const auto settling = [&] {
    return taken < most_steps && !at_rest && !watch.cannot_come_to_rest();
  };
  while (taken < settings_.steps_per_pass || settling()) {
    const auto which = [&] {
      return std::to_string(taken + 1) + (taken < settings_.steps_per_pass
                                               ? " of " + std::to_string(settings_.steps_per_pass)
                                               : " (settling, at most " + std::to_string(most_steps) + ")");
    };
    if (settings_.stop_requested && settings_.stop_requested()) {
      const std::string where = "coupling iteration " + std::to_string(iteration_) + " stopped at DDA step " + which();
      abandon_pass();
      throw PassInterrupted(where);
    }
    try {
      const dda::StepReport step = mechanics_.step();
      report.most_open_close_iterations = std::max(report.most_open_close_iterations, step.open_close_iterations);
      report.step_cuts += step.retries;
      at_rest = mechanics_.is_at_rest(step);
      report.full_time_step = mechanics_.ran_at_full_time_step(step);
      report.shortest_time_step = std::min(report.shortest_time_step, step.time_step);
      pass_squared_steps_ += step.time_step * step.time_step;
      watch.observe(mechanics_.free_drift(), most_steps - (taken + 1));
    } catch (const dda::StepInterrupted&) {
      abandon_pass();
      throw PassInterrupted("coupling iteration " + std::to_string(iteration_) + " stopped within DDA step " + which());
    } catch (const std::exception& e) {
      throw std::runtime_error("DDA step " + which() + " (t = " + std::to_string(mechanics_.time()) + " s): " + e.what());
    }
    ++taken;
  }
  report.settling_steps = taken - settings_.steps_per_pass;
  report.at_rest = settings_.settle_steps == 0 || at_rest;
  const bool stopped_drifting = !report.at_rest && taken < most_steps && watch.cannot_come_to_rest();
  report.drifting_block = stopped_drifting ? watch.drifting_block() : -1;
  // The DDA's contact list goes while the flow model factors and the fields are written.
  mechanics_.release_step_buffers();
  report.mechanics_seconds = seconds_since(start);
  report.time = mechanics_.time();
  report.outside_mesh = outside_mesh();
}

// After a settling pass at the full load whose blocks did not come to rest: each group of
// blocks that met nothing in its last step moved rigidly to where the secant of its net load
// vanishes (float_secant.hpp), so that the next pass's flow sees it there. Steady runs only:
// a transient step's iterations move the blocks under the step's own load.
void StaggeredLoop::move_free_groups(PassReport& report, const std::vector<Point>& start_displacements) {
  const bool applies = settings_.settle_steps > 0 && !time_level_ && report.load_factor == 1.0 && !report.at_rest;
  if (!applies) {
    float_secant_.forget();
    return;
  }
  const std::vector<std::vector<int>> groups =
      find_free_groups(mechanics_.free_drift().landing_steps, mechanics_.contacts());
  float_secant_.keep_only(groups);
  const std::vector<Point> end_displacements = block_displacements();
  for (const std::vector<int>& group : groups) {
    Point start{0.0, 0.0}, end{0.0, 0.0};
    for (int b : group) {
      start += start_displacements[static_cast<std::size_t>(b)];
      end += end_displacements[static_cast<std::size_t>(b)];
    }
    const double n = static_cast<double>(group.size());
    start = {start.x / n, start.y / n};
    end = {end.x / n, end.y / n};
    const Point motion = end - start;
    const double moved = std::hypot(motion.x, motion.y);
    double least_advance = moved;
    for (int b : group) {
      const Point own = end_displacements[static_cast<std::size_t>(b)] - start_displacements[static_cast<std::size_t>(b)];
      if (moved > 0.0) least_advance = std::min(least_advance, geometry::dot(own, motion) / moved);
    }
    const Point shift = float_secant_.shift(group, start, end, least_advance, pass_squared_steps_,
                                            mechanics_.allowed_step_displacement());
    if (shift.x == 0.0 && shift.y == 0.0) continue;
    mechanics_.translate_blocks(group, shift);
    ++report.groups_moved;
    report.longest_group_shift = std::max(report.longest_group_shift, std::hypot(shift.x, shift.y));
  }
}

// The pass's convergence norms against the last pass (the heads' judged unrelaxed), whether it
// converged, diverges or lets blocks escape, and the fields' summary numbers.
void StaggeredLoop::measure_convergence(PassReport& report, double unrelaxed_head_change) {
  const std::vector<Point> u = block_displacements();
  for (std::size_t b = 0; b < u.size(); ++b)
    if (!std::isfinite(u[b].x) || !std::isfinite(u[b].y))
      throw std::runtime_error("the displacement of block " + std::to_string(b) +
                               " is not finite in coupling iteration " + std::to_string(iteration_));
  report.head_change = unrelaxed_head_change;
  report.displacement_change = previous_displacements_.empty()
                                   ? 1.0
                                   : displacement_change(u, previous_displacements_,
                                                         mechanics_.allowed_step_displacement());
  // Both norms compare this pass with the last, so both passes must have had the full load.
  // In a time step, its first pass compares with the last step's end, not with an iterate.
  const bool compared_with_iterate = !time_level_ || time_level_->passes >= 2;
  report.under_tolerance = iteration_ > settings_.ramp_passes && compared_with_iterate &&
                           report.head_change < settings_.tolerance &&
                           report.displacement_change < settings_.tolerance && report.at_rest;
  report.converged = report.under_tolerance && report.full_time_step;
  if (!report.converged) report.escaping = blocks_beyond_their_size();
  report.head_change_two_passes = heads_two_back_.empty() ? 1.0 : head_change(solution_.head, heads_two_back_);
  heads_two_back_ = std::move(previous_heads_);
  previous_heads_ = solution_.head;
  pass_before_displacements_ = std::exchange(previous_displacements_, u);
  const double change = std::max(report.head_change, report.displacement_change);
  growth_.add(change, iteration_, settings_.ramp_passes);
  report.growing_passes = growth_.passes;
  report.diverging = growth_.diverging(settings_.diverging_passes, settings_.diverging_growth);

  double porosity_sum = 0.0;
  for (double phi : porosity_.porosity) porosity_sum += phi;
  report.mean_porosity = porosity_.porosity.empty() ? 0.0 : porosity_sum / porosity_.porosity.size();
  for (double k : permeability_) report.max_permeability = std::max(report.max_permeability, k);
  for (const dda::ContactInfo& c : mechanics_.contacts())
    report.largest_opening = std::max(report.largest_opening, -c.penetration);
}

// The pass counted, its times added, and the DDA system continued from its exported state.
void StaggeredLoop::finish_pass(const PassReport& report) {
  completed_ = iteration_;
  pass_start_.reset();
  seconds_.porosity += report.porosity_seconds;
  seconds_.flow += report.flow_seconds;
  seconds_.forces += report.forces_seconds;
  seconds_.mechanics += report.mechanics_seconds;
  last_mechanics_ = mechanics_.export_state();
  mechanics_.import_state(last_mechanics_);
}

// The pass's flow as a backward-Euler step in pseudo-time from the last pass's heads, in place
// of the steady solve, whose heads gave the convergence norm (`steady_change`): Δτ is first_step at pass 2 and grows or
// shrinks by SER after (pass_storage.hpp). The steady heads are the fixed point of this step.
hydro::FlowSolution StaggeredLoop::step_in_pseudo_time(double steady_change) {
  const PseudoTimeSettings& pseudo = *settings_.pseudo_time;
  if (pseudo_time_step_ == 0.0) pseudo_time_step_ = pseudo.first_step;
  else pseudo_time_step_ = next_pseudo_time_step(pseudo_time_step_, last_steady_change_, steady_change);
  last_steady_change_ = steady_change;
  const std::span<const double> areas = porosity_mapper_.element_areas();
  std::vector<double> open_fraction(areas.size());
  for (std::size_t e = 0; e < areas.size(); ++e) open_fraction[e] = porosity_.fracture_area[e] / areas[e];
  std::vector<double> storage = compute_pass_storage(pseudo, areas, open_fraction, joints_ ? &*joints_ : nullptr,
                                                     joint_apertures_);
  for (double& c : storage) c /= pseudo_time_step_;
  const hydro::PermeabilityView k = permeability_tensors_.empty() ? hydro::PermeabilityView(permeability_)
                                                                  : hydro::PermeabilityView(permeability_tensors_);
  return darcy_.solve_step(k, storage, hydro::MassMatrix::lumped, solution_.head);
}

void StaggeredLoop::abandon_pass() {
  mechanics_.import_state(last_mechanics_);
  if (!pass_start_) return;
  PassStart& start = *pass_start_;
  iteration_ = completed_;
  porosity_ = std::move(start.porosity);
  permeability_ = std::move(start.permeability);
  permeability_tensors_ = std::move(start.permeability_tensors);
  joint_apertures_ = std::move(start.joint_apertures);
  pseudo_time_step_ = start.pseudo_time_step;
  last_steady_change_ = start.last_steady_change;
  if (time_level_) time_level_->passes = start.step_passes;
  if (time_level_ && start.step_gaps) time_level_->gaps = std::move(*start.step_gaps);
  if (start.flow_solved) {  // else the heads and the relaxation are still the last pass's
    solution_ = std::move(start.solution);
    previous_update_ = std::move(start.previous_update);
    relaxation_ = start.relaxation;
    if (settings_.acceleration == Acceleration::anderson) anderson_.restore(std::move(start.anderson_history));
  }
  darcy_.restore_kept_factor(std::move(start.kept_factor), start.kept_factor_single_precision);
  pass_start_.reset();
}

}  // namespace hydrodda::coupling

namespace hydrodda::coupling {

// Relaxes the fresh solution against the last pass's: h ← h_old + ω (h̃ − h_old), and the
// pressures alike. With Aitken's Δ² method (numerics/aitken.hpp) ω follows the last two
// updates r = h̃ − h_old: a loop whose updates flip sign pass after pass (cycling between two
// states) gets ω near 1/2 and settles; one whose updates keep their direction keeps ω near 1.
void StaggeredLoop::relax(hydro::FlowSolution& fresh) {
  if (previous_heads_.empty()) return;
  if (settings_.acceleration == Acceleration::anderson) {
    accelerate_by_anderson(fresh);
    return;
  }
  std::vector<double> update(fresh.head.size());
  for (std::size_t i = 0; i < update.size(); ++i) update[i] = fresh.head[i] - previous_heads_[i];
  if (settings_.acceleration == Acceleration::aitken && previous_update_.size() == update.size())
    relaxation_ = numerics::aitken_relaxation(relaxation_, previous_update_, update);
  previous_update_ = std::move(update);
  const double w = relaxation_;
  if (w == 1.0) return;
  for (std::size_t i = 0; i < fresh.head.size(); ++i) {
    fresh.head[i] = previous_heads_[i] + w * (fresh.head[i] - previous_heads_[i]);
    fresh.pressure[i] = solution_.pressure[i] + w * (fresh.pressure[i] - solution_.pressure[i]);
  }
}

// Anderson acceleration of the loop's fixed point x = G(x) (numerics::AndersonAccelerator: Walker &
// Ni 2011, alg. AA), x the heads and pressures a pass's forces come from and G(x) the next
// pass's solve on the blocks those forces moved:
//   f_k = G(x_k) − x_k;  γ = argmin ‖f_k − ΔF γ‖₂ over the last anderson_depth passes;
//   x_{k+1} = G(x_k) − ΔG γ,  then x_old + ω (x_{k+1} − x_old) with relaxation ω.
// Heads and pressures go in one vector: the pressure is ρ_w g h plus a fixed term at each node
// (either convention), so its part of every difference is ρ_w g times the heads' and γ is the
// one the heads alone give, while the pressures take exactly the same mix. The mix has weights
// summing to one, so fixed heads on the boundary stay as set. A jacked joint that fills with
// pressure and closes again swings the plain loop between two states; the secant information
// of the last few passes lands between them.
void StaggeredLoop::accelerate_by_anderson(hydro::FlowSolution& fresh) {
  const auto n = static_cast<Eigen::Index>(fresh.head.size());
  Eigen::VectorXd x(2 * n), g(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    x[i] = previous_heads_[i];
    x[n + i] = solution_.pressure[i];
    g[i] = fresh.head[i];
    g[n + i] = fresh.pressure[i];
  }
  const Eigen::VectorXd mixed = anderson_.next(x, g);
  const double w = settings_.relaxation;
  for (Eigen::Index i = 0; i < n; ++i) {
    fresh.head[i] = x[i] + w * (mixed[i] - x[i]);
    fresh.pressure[i] = x[n + i] + w * (mixed[n + i] - x[n + i]);
  }
}

}  // namespace hydrodda::coupling
