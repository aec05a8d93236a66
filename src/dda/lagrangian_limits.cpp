// What a step's try does when its augmented Lagrangian passes run out (System::solve_step).
//
// The passes end with every closed contact within the penetration tolerance of touching. A
// try at a step so short that the blocks' inertia M/Δt² outweighs the penalty p by orders
// cannot get there: a Lagrangian pass moves a contact by p/(M/Δt² + p) of the distance it
// measures, next to nothing, and a shorter step moves it less, so cutting the step, the
// remedy for forces that did not settle, only deepens the lock
// (docs/studies/2026-11-29-contacts-at-the-tolerance.md). Two contacts end there:
//
//  - a closed contact whose vertex stands off its edge by more than the tolerance, held off by
//    the blocks around it, its multiplier compressive from an earlier geometry: it touches
//    nothing and carries no force. It opens, a change of state for the open–close iteration
//    rather than a shorter step (Shi 1988 §5, and ntdda's open–close check, open_close in
//    combineddf.c: a closed contact opens when its vertex lies off the edge by more than the
//    open criterion);
//  - a closed contact at the tolerance itself, a hair past it: the last step's update (its
//    rotations exact, its penetrations linear) left it 1e-9 of the tolerance past it, or this
//    step's load pushes it on by 1e-11 of it, where its multiplier would have to carry the
//    pushing load to stop it and a pass raises it by p × the tolerance (6e5 N/m on the faulted
//    seal, against 1e8 N/m). When the passes no longer move the blocks (the last moved no
//    vertex by 1% of the tolerance, the length a step resolves), the try is accepted if no
//    overlap is past the tolerance, or past what the step started with (up to twice the
//    tolerance), by more than 1e-6 of the tolerance: the step did not deepen it. Its passes'
//    multipliers are kept, and the longer steps that follow push it back within the tolerance.
//    An overlap deeper than twice the tolerance is no contact at the tolerance, and a step
//    that cannot push it out is cut and fails as before.
//
// A short step's normal springs (normal_spring). A step cut short for any reason (its contact
// states chattering) makes its passes slow: a closed contact's overlap shrinks by K/(K + p) a
// pass, K ≥ 2M/Δt² of its blocks, so at 2M/Δt² = p half of it is left each pass, the forces do
// not settle, and the step is cut again, shorter and slower. Under the augmented Lagrangian the
// answer of a pass that settles does not depend on the normal penalty (every overlap within
// the tolerance, the multiplier carrying the force): only the rate does. So before a step whose
// forces did not settle (after its try at twice the passes, and its mixed try) is cut for an
// overlap past the tolerance whose blocks' inertia rivals p, it is tried again at its length
// with the joints' normal springs at kInertiaOverPenalty × 2M/Δt² of the lighter movable block
// where that is above p, so that a pass leaves at most a tenth of an overlap; at most
// kMostPenaltyRaise × p (the matrix no worse conditioned than by ten fixed points' springs of
// 10 p), where the step is cut as before. So are the tries of the cuts after it; a step that
// settled without them is untouched. The shear springs keep p (a locked contact's shear force
// is p × its spring's stretch, which a stiffer spring would change), the pure penalty method
// keeps p (there p is the contact's stiffness). Not in a model with bonds: the Brazilian disc's
// run took three times as long with it, to the same end. On the faulted seal just under its
// lift-off the breach bracket is then the same on its mesh and on the mesh halved
// (docs/studies/2026-12-01-short-steps-normal-springs.md).
//
// Passes that contract slowly: while the contact states stand, λ ← λ + p d is an affine map
// of the multipliers, contracting by K/(K + p) a pass, K the stiffness holding a contact's
// vertex. Where K ≫ p (a sub-block's corner held by the locked contacts of the bonded cells
// about it, K ≈ 33 p: docs/studies/2026-11-30-strip-seal-lagrangian.md) it needs some 90
// passes; Anderson's mixing of the last five (Walker & Ni 2011, alg. AA) solves an affine map
// in a few. They mix only where the step would otherwise be cut: after a try and a
// try at twice the passes whose forces did not settle, the step is tried once more at the same
// length with them mixed from its pass kPlainLagrangianPasses on, and so are the tries of the
// cuts after it; a step that settled without them is untouched (update_multipliers). Only where
// the blocks about the overlaps hold them, not their inertia: where 2M/Δt² of a block at an
// overlap past the tolerance outweighs its normal spring, the exact solution of the step
// pushes it out by a force of its inertia, which a static step's shortness makes arbitrary (a
// block 3 µm into the base at 1e-10 s: 1e18 N/m), and the step is cut and fails as above.
//
// Passes that stalled moved nothing but the multipliers: λ ← λ + p d on every closed contact,
// while the one past the tolerance kept them going. A contact already within the tolerance,
// standing off its edge by d < 0, lost p |d| a pass, 30 a try: the tessellated seal's joints
// standing 1e-8 to 5e-7 m off, at 3e-8 s, slid and opened, some 40 a pass, until the step
// fell below any use. Those contacts take back the multipliers they started the open–close
// pass with; the one past the tolerance keeps what it learnt.

#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/system.hpp"

namespace hydrodda::dda {

char System::open_contacts_standing_off() {
  char seen = 0;
  for (int i : closed_) {
    ActiveContact& c = active_[i];
    ContactRecord& r = c.record;
    // An intact bond's contacts stay locked: its face breaks as a whole (update_state).
    if (is_intact_bond(c.key) || r.penetration >= -penetration_tolerance_) continue;
    note_state_change(c, open_close_pass_, r.state, c.pass_penetration);
    c.pass_penetration = r.penetration;
    r.state = ContactState::open;
    r.multiplier = 0.0;
    r.normal_force = 0.0;
    r.released = false;  // parted by more than the tolerance: it closes again at the band
    seen |= c.changed_in_step ? 3 : 1;
    c.changed_in_step = true;
  }
  return seen;
}

double System::normal_spring(const ActiveContact& c) const {
  return stiff_normal_springs_ ? stiffened_normal_spring(c) : c.stiffness;
}

bool System::overlaps_slowed_by_inertia() const {
  if (!bond_sides_.empty()) return false;  // not with bonds (above)
  for (int i : closed_) {
    const ActiveContact& c = active_[i];
    if (c.record.penetration > penetration_tolerance_ && stiffened_normal_spring(c) > c.stiffness) return true;
  }
  return false;
}

double System::step_inertia(const Block& block) const {
  return 2.0 * materials_[block.material].density * block.moments.area / (dt_ * dt_);
}

double System::stiffened_normal_spring(const ActiveContact& c) const {
  if (settings_.contact != ContactMethod::augmented_lagrangian) return c.stiffness;
  double lighter = std::numeric_limits<double>::infinity();  // the lighter movable block's
  for (int b : {c.key.block_i, c.key.block_j}) {
    const Block& block = blocks_[static_cast<std::size_t>(b)];
    if (block.dof >= 0) lighter = std::min(lighter, step_inertia(block));
  }
  if (!std::isfinite(lighter)) return c.stiffness;
  return std::clamp(kInertiaOverPenalty * lighter, c.stiffness, kMostPenaltyRaise * c.stiffness);
}

bool System::overlaps_held_by_the_blocks_around() const {
  bool any = false;
  for (int i : closed_) {
    const ActiveContact& c = active_[i];
    if (!(c.record.penetration > penetration_tolerance_)) continue;
    any = true;
    for (int b : {c.key.block_i, c.key.block_j}) {
      const Block& block = blocks_[static_cast<std::size_t>(b)];
      // Against the penalty p (a bonded face's own spring aside), or the stiffened spring.
      if (block.dof >= 0 && step_inertia(block) > (stiff_normal_springs_ ? c.normal_stiffness : penalty_)) return false;
    }
  }
  return any;
}

void System::update_multipliers(int pass, numerics::AndersonAccelerator& mixing) {
  if (!mixing_multipliers_ || pass + 1 < kPlainLagrangianPasses) {
    for (int i : closed_) active_[i].record.multiplier = active_[i].record.normal_force;
    return;
  }
  Eigen::VectorXd multipliers(closed_.size()), forces(closed_.size());
  for (std::size_t k = 0; k < closed_.size(); ++k) {
    multipliers[static_cast<Eigen::Index>(k)] = active_[closed_[k]].record.multiplier;
    forces[static_cast<Eigen::Index>(k)] = active_[closed_[k]].record.normal_force;
  }
  const Eigen::VectorXd mixed = mixing.next(multipliers, forces);
  for (std::size_t k = 0; k < closed_.size(); ++k)
    active_[closed_[k]].record.multiplier = mixed[static_cast<Eigen::Index>(k)];
}

bool System::overlaps_held(double growth) const {
  const double slack = 1e-6 * penetration_tolerance_;
  for (int i : closed_) {
    const ActiveContact& c = active_[i];
    const double started = std::min(c.penetration0, 2.0 * penetration_tolerance_);
    if (c.record.penetration > std::max(growth * penetration_tolerance_ + slack, started)) return false;
  }
  return true;
}

System::ContactForceExtent System::undo_stalled_updates_within_tolerance(const Eigen::VectorXd& d) {
  for (std::size_t k = 0; k < closed_.size(); ++k) {
    ActiveContact& c = active_[closed_[k]];
    if (std::abs(c.record.penetration) <= penetration_tolerance_) c.record.multiplier = pass_start_multipliers_[k];
  }
  return update_contact_forces(d);
}

void System::keep_tried_multipliers() {
  tried_multipliers_.clear();
  for (const ActiveContact& c : active_)  // in key order
    // Its normal force λ + p d: the multiplier the next pass would have taken.
    if (c.record.state != ContactState::open) tried_multipliers_.emplace_back(c.key, c.record.normal_force);
}

void System::start_from_tried_multipliers() {
  auto tried = tried_multipliers_.begin();
  for (ActiveContact& c : active_) {  // both in key order
    while (tried != tried_multipliers_.end() && tried->first < c.key) ++tried;
    if (tried == tried_multipliers_.end()) break;
    if (tried->first == c.key && c.record.state != ContactState::open) c.record.multiplier = tried->second;
  }
}

}  // namespace hydrodda::dda
