// Export and import of a System's evolving state (see SystemState), for checkpoints.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "dda/system.hpp"

namespace hydrodda::dda {

namespace {

void check_count(std::size_t got, std::size_t expected, const char* what) {
  if (got != expected)
    throw std::invalid_argument("DDA state: " + std::to_string(got) + " " + what + " where the model has " +
                                std::to_string(expected));
}

}  // namespace

SystemState System::export_state() const {
  SystemState s;
  for (const Block& b : blocks_) {
    SystemState::BlockState bs;
    bs.polygon = b.polygon;
    for (int i = 0; i < 6; ++i) bs.velocity[i] = b.velocity[i];
    for (int i = 0; i < 3; ++i) {
      bs.stress[i] = b.stress[i];
      bs.strain[i] = b.strain[i];
    }
    bs.rotation = b.rotation;
    bs.material_centroid = b.material_centroid;
    s.blocks.push_back(std::move(bs));
  }
  s.time = time_;
  s.time_step = dt_;
  s.contacts.assign(records_.begin(), records_.end());
  for (const TrackedPoint& p : fixed_points_) s.fixed_points.push_back(p.position);
  for (const TrackedPoint& p : load_points_) s.load_points.push_back(p.position);
  for (const TrackedPoint& p : displacement_points_) s.displacement_points.push_back(p.position);
  for (const TrackedPoint& p : measured_) s.measured_points.push_back(p.position);
  s.vertex_forces = vertex_forces_;
  for (const RollerPoint& r : rollers_) s.roller_reliefs.push_back(r.relief);
  s.bond_breaks = bond_breaks_;
  s.softening_bonds = softening_;
  return s;
}

void System::import_state(const SystemState& s) {
  // Check everything before changing anything, so a state that does not fit leaves the
  // system as it was.
  check_count(s.blocks.size(), blocks_.size(), "blocks");
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    check_count(s.blocks[b].polygon.size(), blocks_[b].polygon.size(), "vertices of a block");
  check_count(s.fixed_points.size(), fixed_points_.size(), "fixed points");
  check_count(s.load_points.size(), load_points_.size(), "load points");
  check_count(s.displacement_points.size(), displacement_points_.size(), "prescribed-displacement points");
  check_count(s.measured_points.size(), measured_.size(), "measured points");
  check_count(s.vertex_forces.size(), blocks_.size(), "vertex-force lists");
  check_count(s.roller_reliefs.size(), rollers_.size(), "roller reliefs");
  for (std::size_t b = 0; b < blocks_.size(); ++b)
    if (!s.vertex_forces[b].empty())
      check_count(s.vertex_forces[b].size(), blocks_[b].polygon.size(), "vertex forces of a block");
  for (const auto& [key, record] : s.contacts) {
    const bool fits = key.block_i >= 0 && key.block_i < block_count() && key.block_j >= 0 &&
                      key.block_j < block_count() && key.vertex >= 0 &&
                      key.vertex < static_cast<int>(blocks_[key.block_i].polygon.size()) && key.edge >= 0 &&
                      key.edge < static_cast<int>(blocks_[key.block_j].polygon.size());
    if (!fits) throw std::invalid_argument("DDA state: a contact names a missing block, vertex or edge");
  }
  if (!(s.time_step > 0)) throw std::invalid_argument("DDA state: the time step must be > 0");
  for (const BondBreak& b : s.bond_breaks)
    if (b.bond < 0 || b.bond >= bond_count()) throw std::invalid_argument("DDA state: a broken bond the model does not have");

  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    Block& blk = blocks_[b];
    const SystemState::BlockState& bs = s.blocks[b];
    blk.polygon = bs.polygon;
    blk.moments = compute_moments(blk.polygon);  // as commit_step derives them
    for (int i = 0; i < 6; ++i) blk.velocity[i] = bs.velocity[i];
    for (int i = 0; i < 3; ++i) {
      blk.stress[i] = bs.stress[i];
      blk.strain[i] = bs.strain[i];
    }
    blk.rotation = bs.rotation;
    blk.material_centroid = bs.material_centroid;
  }
  time_ = s.time;
  dt_ = s.time_step;
  // In key order, the first of any repeated key kept.
  records_.assign(s.contacts.begin(), s.contacts.end());
  const auto key_less = [](const auto& a, const auto& b) { return a.first < b.first; };
  std::stable_sort(records_.begin(), records_.end(), key_less);
  records_.erase(std::unique(records_.begin(), records_.end(),
                             [](const auto& a, const auto& b) { return a.first == b.first; }),
                 records_.end());
  active_.clear();
  closed_.clear();
  const auto restore = [](std::vector<TrackedPoint>& points, const std::vector<Point>& positions) {
    for (std::size_t i = 0; i < points.size(); ++i) points[i].position = positions[i];
  };
  restore(fixed_points_, s.fixed_points);
  restore(load_points_, s.load_points);
  restore(displacement_points_, s.displacement_points);
  restore(measured_, s.measured_points);
  vertex_forces_ = s.vertex_forces;
  for (std::size_t i = 0; i < rollers_.size(); ++i) rollers_[i].relief = s.roller_reliefs[i];
  bond_breaks_ = s.bond_breaks;
  pending_breaks_.clear();
  last_cut_try_breaks_.clear();
  bond_broken_.assign(bond_sides_.size(), 0);
  for (int bond : broken_at_start_) bond_broken_[static_cast<std::size_t>(bond)] = 1;
  for (const BondBreak& b : bond_breaks_) bond_broken_[static_cast<std::size_t>(b.bond)] = 1;
  softening_ = s.softening_bonds;
  pending_softening_.clear();
  for (const SofteningBond& b : softening_) {
    if (b.bond < 0 || static_cast<std::size_t>(b.bond) >= bond_sides_.size())
      throw std::invalid_argument("DDA: the state names softening bond " + std::to_string(b.bond) + ", and there are " +
                                  std::to_string(bond_sides_.size()));
    bond_broken_[static_cast<std::size_t>(b.bond)] = 2;
  }
  start_face_share_ = nullptr;  // relieve_start_loads gives it again before a first step
  // Contacts carry the initial stress from the first step only.
  preload_new_contacts_ = initial_stress_ && s.time == 0.0 && s.contacts.empty();
  solver_->reset();
  contact_search_.forget();
}

}  // namespace hydrodda::dda
