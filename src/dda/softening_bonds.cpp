// Softening bonds: a bond whose joint type has a fracture energy G_f does not break when its
// face's normal traction reaches T; it starts to open, held by a cohesive traction that falls
// linearly with the opening w (Hillerborg, Modéer & Petersson 1976, the fictitious crack; the
// linear law of Petersson 1981):
//   σ(w) = T (1 − w/w_c),  w_c = 2 G_f / T,  so that ∫₀^{w_c} σ dw = G_f,
// and breaks, a joint of its type, once w ≥ w_c at both ends of its face. Shear keeps the
// strength break (no mixed-mode softening).
//
// A softening spring (dσ/dw < 0) in the block matrix would make it indefinite. So the traction
// is a load on the two faces, as the fluid's pressure is on a joint's, and the face's contacts
// are a broken joint's (no tension, friction only) meanwhile:
//   each open–close pass: loads F_coh(w) with w from the last pass's solution (the step's
//     start in the first); after the solve, σ(w_new) against the σ the loads were made with;
//     a change above 1e-3 T → another pass (a fixed point w ← C (F − σ(w) L), C the
//     structure's compliance, that converges while the structure is stiffer than the
//     softening, |dσ/dw| L C = T L C / w_c < 1: the stable softening a quasi-static load
//     path can follow; past it, under a load held, w grows pass after pass to w_c and the bond
//     breaks, as the crack then runs).
// The law is read at each end of the face from that end's opening, the traction linear
// between them (its loads exact for the blocks' linear displacement: compute_edge_traction_load).
// Closing holds the traction reached: σ = T (1 − max(w, w_peak)/w_c), w_peak the largest
// opening of a committed step (a secant back to the origin, T w / w_peak, is a spring of
// stiffness T / w_peak, which applied as a lagged load would not converge at a small w_peak).
#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/block_kernels.hpp"
#include "dda/system.hpp"

namespace hydrodda::dda {

namespace {
constexpr double kSettledShare = 1e-3;  // of T: a pass's tractions within it of those it used
// Passes of a try whose cohesive loads have not settled since the map last changed, after
// which the zone is taken to have no equilibrium (below the peak the mixing settles in far
// fewer: docs/studies/2026-11-29-softening-bonds.md).
constexpr int kRunningPasses = 20;
}  // namespace

std::array<double, 2> System::opening_after(int bond, const Eigen::VectorXd& d) const {
  const std::array<BondSide, 2>& sides = bond_sides_[static_cast<std::size_t>(bond)];
  const auto ends = [&](const BondSide& side) {
    const Block& b = blocks_[static_cast<std::size_t>(side.block)];
    const std::size_t e = static_cast<std::size_t>(side.edge);
    std::array<Point, 2> p{b.polygon[e], b.polygon[(e + 1) % b.polygon.size()]};
    if (d.size() > 0 && b.dof >= 0) {
      const BlockMotion motion(b.moments.centroid, d.segment<6>(6 * b.dof));
      p = {motion(p[0]), motion(p[1])};
    }
    return p;
  };
  const std::array<Point, 2> a = ends(sides[0]);
  const std::array<Point, 2> b = ends(sides[1]);  // the same face the other way round
  const Point t = (a[1] - a[0]) / geometry::distance(a[0], a[1]);
  const Point n{t.y, -t.x};  // out of the first sub-block, towards the second
  return {dot(n, b[1] - a[0]), dot(n, b[0] - a[1])};
}

std::array<double, 2> System::bond_opening(int bond) const { return opening_after(bond, Eigen::VectorXd()); }

std::array<double, 2> System::bond_cohesive_traction(int bond, std::array<double, 2> opening) const {
  const JointStrength& j = joints_[static_cast<std::size_t>(bond_joint_type(bond))];
  std::array<double, 2> peak{0.0, 0.0};
  for (const SofteningBond& s : softening_)
    if (s.bond == bond) peak = s.peak_opening;
  const double critical = 2.0 * j.fracture_energy / j.tensile_strength;  // w_c
  std::array<double, 2> traction{};
  for (std::size_t k = 0; k < 2; ++k)
    traction[k] = j.tensile_strength * std::max(0.0, 1.0 - std::max(opening[k], peak[k]) / critical);
  return traction;
}

void System::restart_cohesive_mixing() {
  cohesion_next_.resize(0);
  cohesion_mixing_.reset();
  cohesion_passes_ = 0;
}

void System::add_cohesive_loads(const Eigen::VectorXd& d, Eigen::VectorXd& f) {
  // The step's first pass, or a set of softening bonds that changed: the map is new.
  if (d.size() == 0 || cohesion_next_.size() != static_cast<Eigen::Index>(2 * softening_.size()))
    restart_cohesive_mixing();
  const bool mixed = cohesion_next_.size() > 0;
  cohesion_used_.assign(softening_.size(), {0.0, 0.0});
  for (std::size_t i = 0; i < softening_.size(); ++i) {
    const int bond = softening_[i].bond;
    if (bond_broken_[static_cast<std::size_t>(bond)] != 2) continue;  // broke in this try
    const std::array<double, 2> sigma = mixed ? std::array<double, 2>{cohesion_next_[2 * i], cohesion_next_[2 * i + 1]}
                                              : bond_cohesive_traction(bond, opening_after(bond, d));
    cohesion_used_[i] = sigma;
    // A pull on each face towards the other: tension on both (normal positive outward).
    const std::array<BondSide, 2>& sides = bond_sides_[static_cast<std::size_t>(bond)];
    for (std::size_t s = 0; s < 2; ++s) {
      const Block& b = blocks_[static_cast<std::size_t>(sides[s].block)];
      if (b.dof < 0) continue;
      const std::size_t e = static_cast<std::size_t>(sides[s].edge);
      // The second face runs the other way: its start is the first face's end.
      const double at_start = s == 0 ? sigma[0] : sigma[1];
      const double at_end = s == 0 ? sigma[1] : sigma[0];
      f.segment<6>(6 * b.dof) += compute_edge_traction_load(b.polygon[e], b.polygon[(e + 1) % b.polygon.size()],
                                                            b.moments.centroid, at_start, at_end, 0.0, 0.0);
    }
  }
}

// No equilibrium of the cohesive zone at this load (past the peak of a load held): the crack
// runs. Its most open softening face, at the zone's trailing end next to the open crack, is
// let go (broken), and the zone ahead is sought again; repeated, the crack runs until the
// zone finds an equilibrium (it arrests) or the path is cut through.
bool System::release_most_open_bond(const Eigen::VectorXd& d) {
  int chosen = -1;
  double widest = -std::numeric_limits<double>::infinity();
  for (const SofteningBond& s : softening_) {
    if (bond_broken_[static_cast<std::size_t>(s.bond)] != 2) continue;
    const JointStrength& j = joints_[static_cast<std::size_t>(bond_joint_type(s.bond))];
    const std::array<double, 2> w = opening_after(s.bond, d);
    const double share = std::max(w[0], w[1]) / (2.0 * j.fracture_energy / j.tensile_strength);
    if (share > widest) {
      widest = share;
      chosen = s.bond;
    }
  }
  if (chosen < 0) return false;
  bond_broken_[static_cast<std::size_t>(chosen)] = 1;
  pending_breaks_.emplace_back(chosen, BondFailure::tension);
  return true;
}

// Pseudocode (the cohesive fixed point x = G(x), x the faces' tractions the loads were made
// with, G(x) = σ(w(x)) those the solution's openings give; Walker & Ni 2011, Anderson
// acceleration, as the friction loads):
//   G(x) within 1e-3 T of x at every face → settled
//   a face open past w_c at both ends → broken; the map is new (plain step next)
//   some contact changed state in the pass → the map is new: the mixing's history is dropped
//   else x ← AA(x, G(x)) clipped to [0, T]; a traction clipped back to where it was →
//     x ← G(x), the history dropped; after kRunningPasses without settling, the zone has
//     no equilibrium: the crack runs (release_most_open_bond)
// The plain iteration x ← G(x) contracts by T L C / w_c a pass (C the compliance at the
// face), which tends to 1 as the zone grows to the peak; the mixing's secant model of G
// settles it in a few passes there (docs/studies/2026-11-29-softening-bonds.md).
// Why the two restarts: passes of two maps (the contacts' states, hence the matrix, differ)
// aim the secant model at neither's fixed point; and an iterate clipped to the bounds is not
// the one the secant model asked for, so the next pass repeats it with the same residual
// (projected Anderson stagnates): on the coarse plate of the study a face that had just started
// to soften sat at x = T with G(x) = 0.93 T for six passes until the contacts about it changed
// state, and the step, cut and cut again, ended the run at 0.91 σ_c (the same study).
System::CohesionChange System::settle_cohesive_loads(const Eigen::VectorXd& d, bool contacts_changed) {
  CohesionChange change = CohesionChange::none;
  const std::size_t used = std::min(softening_.size(), cohesion_used_.size());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(2 * softening_.size()));
  Eigen::VectorXd image = x;
  Eigen::VectorXd ceiling = x;
  for (std::size_t i = 0; i < used; ++i) {
    const int bond = softening_[i].bond;
    if (bond_broken_[static_cast<std::size_t>(bond)] != 2) continue;
    const JointStrength& j = joints_[static_cast<std::size_t>(bond_joint_type(bond))];
    const std::array<double, 2> opening = opening_after(bond, d);
    const std::array<double, 2> sigma = bond_cohesive_traction(bond, opening);
    if (sigma[0] == 0.0 && sigma[1] == 0.0) {  // open past w_c along all of it: broken
      bond_broken_[static_cast<std::size_t>(bond)] = 1;
      pending_breaks_.emplace_back(bond, BondFailure::tension);
      change = CohesionChange::broke;
      continue;
    }
    for (std::size_t k = 0; k < 2; ++k) {
      x[static_cast<Eigen::Index>(2 * i + k)] = cohesion_used_[i][k];
      image[static_cast<Eigen::Index>(2 * i + k)] = sigma[k];
      ceiling[static_cast<Eigen::Index>(2 * i + k)] = j.tensile_strength;
    }
    const double moved = std::max(std::abs(sigma[0] - cohesion_used_[i][0]), std::abs(sigma[1] - cohesion_used_[i][1]));
    if (moved > kSettledShare * j.tensile_strength && change == CohesionChange::none) change = CohesionChange::moved;
  }
  if (change == CohesionChange::moved && ++cohesion_passes_ > kRunningPasses && release_most_open_bond(d))
    change = CohesionChange::broke;
  if (change == CohesionChange::broke || used != softening_.size()) {
    restart_cohesive_mixing();
    return change;
  }
  if (contacts_changed) cohesion_mixing_.reset();
  const Eigen::VectorXd mixed = cohesion_mixing_.next(x, image);
  cohesion_next_ = mixed.cwiseMax(0.0).cwiseMin(ceiling);
  // A traction the bounds hold where it already was: the mixing would ask for it again.
  for (Eigen::Index k = 0; k < mixed.size(); ++k)
    if (cohesion_next_[k] != mixed[k] && cohesion_next_[k] == x[k]) {
      cohesion_mixing_.reset();
      cohesion_next_ = image;
      break;
    }
  return change;
}

void System::start_softening(int bond) {
  bond_broken_[static_cast<std::size_t>(bond)] = 2;
  softening_.push_back({bond, {0.0, 0.0}});
  pending_softening_.push_back(bond);
}

// A try that is cut: the bonds it broke out of softening soften again (their pending breaks
// were set intact by the caller), and those that started to soften in it are intact again.
void System::undo_pending_softening() {
  for (const SofteningBond& s : softening_) bond_broken_[static_cast<std::size_t>(s.bond)] = 2;
  for (int bond : pending_softening_) bond_broken_[static_cast<std::size_t>(bond)] = 0;
  std::erase_if(softening_, [&](const SofteningBond& s) { return bond_broken_[static_cast<std::size_t>(s.bond)] == 0; });
  pending_softening_.clear();
}

// The step is kept: its broken bonds leave the softening ones, and the others' peak openings
// take the committed geometry's.
void System::commit_softening() {
  std::erase_if(softening_, [&](const SofteningBond& s) { return bond_broken_[static_cast<std::size_t>(s.bond)] == 1; });
  for (SofteningBond& s : softening_) {
    const std::array<double, 2> w = bond_opening(s.bond);
    for (std::size_t k = 0; k < 2; ++k) s.peak_opening[k] = std::max(s.peak_opening[k], w[k]);
  }
  pending_softening_.clear();
}

}  // namespace hydrodda::dda
