// A static step's unbalanced force: whether the blocks are at rest, or still pushed.
//
// A static DDA step starts each block from rest and solves (K + 2M/Δt²) d = r, r the load
// the step's start leaves unbalanced (Shi 1988, §2.4, the inertia term with v = 0). So
// 2M d/Δt² is the force the step's inertia carries: for a body held by nothing it is the whole
// unbalanced force (K d = 0 for a rigid motion), for one held by contacts or springs a lower
// bound of it. Its resultant on a block is 2 m d_c/Δt², m = ρA and d_c the centroid's
// displacement (about the centroid the mass matrix has no coupling of the translations to the
// rotation or the strains). It is measured against the magnitudes of the forces on the
// block, as Itasca's UDEC and 3DEC judge equilibrium by a local force ratio, the unbalanced
// force over the forces acting (limit 1e-5 by default; Itasca 3DEC 9.0 manual, "Reaching
// Equilibrium"):
//   ratio_b = 2 m_b |d_c,b| / Δt²  /  (|m_b g| + Σ |applied resultants| + Σ |support springs' forces|
//                                      + Σ |contact normal forces|)
// The ratio is 1 for a free body under gravity whatever Δt, where the step displacement
// ½ g Δt² is small at a short step.

#include <algorithm>
#include <cmath>

#include "dda/system.hpp"

namespace hydrodda::dda {

std::vector<double> System::force_magnitudes() const {
  std::vector<double> force(blocks_.size(), 0.0);
  const double g = std::hypot(settings_.gravity.x, settings_.gravity.y);
  for (std::size_t bi = 0; bi < blocks_.size(); ++bi) {
    const Block& b = blocks_[bi];
    force[bi] = materials_[b.material].density * b.moments.area * g;
    // Each vertex force on its own: the fluid's pushes on opposite faces are forces on the block
    // even where they nearly cancel.
    if (bi < vertex_forces_.size())
      for (Point f : vertex_forces_[bi]) force[bi] += std::hypot(f.x, f.y);
  }
  const double load_time = held_load_time_.value_or(time_);
  for (std::size_t i = 0; i < point_loads_.size(); ++i)
    force[load_points_[i].block] +=
        std::hypot(point_loads_[i].force.value(load_time, 0), point_loads_[i].force.value(load_time, 1));
  for (const EdgeTraction& tr : tractions_) {
    const Block& b = blocks_[tr.block];
    const std::size_t n = b.polygon.size();
    const Vector6 load = compute_edge_traction_load(
        b.polygon[tr.edge], b.polygon[(tr.edge + 1) % n], b.moments.centroid, tr.normal_start.value(load_time),
        tr.normal_end.value(load_time), tr.shear_start.value(load_time), tr.shear_end.value(load_time));
    force[tr.block] += std::hypot(load[0], load[1]);
  }
  // The supports' springs: fixed points and prescribed displacements pull their point towards
  // its target, rollers push along their normal (System::assemble_blocks' springs, at the
  // step's end).
  for (const TrackedPoint& f : fixed_points_) force[f.block] += fixed_stiffness_ * geometry::distance(f.position, f.initial);
  for (std::size_t i = 0; i < displacements_.size(); ++i) {
    const TrackedPoint& tp = displacement_points_[i];
    const double ramp = std::min(1.0, time_ / displacements_[i].ramp_time);
    force[tp.block] += fixed_stiffness_ * geometry::distance(tp.position, tp.initial + ramp * displacements_[i].value);
  }
  for (const RollerPoint& r : rollers_) {
    const Point at = blocks_[r.roller.block].polygon[r.roller.vertex];
    force[r.roller.block] +=
        std::abs(fixed_stiffness_ * dot(r.roller.normal, at - r.initial) + r.roller.preload - r.relief);
  }
  // A contact's normal force acts on both of its blocks.
  for (const auto& [key, r] : records_) {
    if (r.state == ContactState::open) continue;
    force[key.block_i] += std::abs(r.normal_force);
    force[key.block_j] += std::abs(r.normal_force);
  }
  return force;
}

void System::measure_unbalanced_force(const std::vector<Point>& step_translation, double dt, StepReport& report) const {
  const std::vector<double> force = force_magnitudes();
  report.unbalanced_force_ratio = 0.0;
  report.unbalanced_block = -1;
  for (std::size_t bi = 0; bi < blocks_.size(); ++bi) {
    const Block& b = blocks_[bi];
    if (b.dof < 0) continue;
    const double mass = materials_[b.material].density * b.moments.area;
    const double inertial = 2.0 * mass * std::hypot(step_translation[bi].x, step_translation[bi].y) / (dt * dt);
    if (inertial == 0.0) continue;
    // A block on which nothing acts and that still moves is as unbalanced as can be.
    const double ratio = force[bi] > 0.0 ? inertial / force[bi] : 1.0;
    if (ratio > report.unbalanced_force_ratio) {
      report.unbalanced_force_ratio = ratio;
      report.unbalanced_block = static_cast<int>(bi);
    }
  }
}

}  // namespace hydrodda::dda
