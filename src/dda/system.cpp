#include "dda/system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "dda/array_growth.hpp"
#include "dda/initial_stress.hpp"
#include "dda/number_text.hpp"
#include "numerics/parallel.hpp"
#include "numerics/anderson.hpp"

namespace hydrodda::dda {

namespace {

// Contacts and blocks per chunk of the loops shared between threads: the same chunks on any
// machine, a few thousand in a large model, each long enough to outlast its scheduling.
constexpr std::size_t kContactChunk = 1024;
constexpr std::size_t kBlockChunk = 128;

void add_segment(Eigen::VectorXd& f, int dof, const Vector6& v) {
  if (dof >= 0) f.segment<6>(6 * dof) += v;
}

bool is_closed(ContactState s) { return s != ContactState::open; }

}  // namespace

System::JointStrength System::strength_of(const Joint& j) {
  return {std::tan(j.friction_angle_deg * std::numbers::pi / 180.0), j.cohesion, j.tensile_strength, j.fracture_energy};
}

System::System(ModelDefinition def, std::unique_ptr<LinearSolver> solver)
    : materials_(std::move(def.materials)),
      settings_(def.settings),
      point_loads_(std::move(def.point_loads)),
      displacements_(std::move(def.displacements)),
      tractions_(std::move(def.tractions)),
      solver_(std::move(solver)) {
  if (def.blocks.empty()) throw std::invalid_argument("DDA: no blocks");
  if (materials_.empty()) throw std::invalid_argument("DDA: no materials");
  if (settings_.time_step <= 0) throw std::invalid_argument("DDA: time_step must be > 0");
  geometry::Box all;
  double young_max = 0.0;
  for (const Material& m : materials_) {
    if (m.young <= 0 || m.density <= 0 || m.poisson <= -1 || m.poisson >= 0.5)
      throw std::invalid_argument("DDA: material needs young > 0, density > 0, -1 < poisson < 0.5");
    elasticity_.push_back(compute_elasticity(m, settings_.plane));
    young_max = std::max(young_max, m.young);
  }
  for (std::size_t b = 0; b < def.blocks.size(); ++b) {
    const BlockDefinition& bd = def.blocks[b];
    const std::string name = "DDA: block " + std::to_string(b) + ": ";
    if (bd.polygon.size() < 3) throw std::invalid_argument(name + "fewer than 3 vertices");
    if (geometry::signed_area(bd.polygon) <= 0)
      throw std::invalid_argument(name + "not counter-clockwise");
    if (geometry::find_self_intersection(bd.polygon))
      throw std::invalid_argument(name + "self-intersecting");
    if (bd.material < 0 || bd.material >= static_cast<int>(materials_.size()))
      throw std::invalid_argument(name + "material index out of range");
    Block blk;
    blk.polygon = bd.polygon;
    blk.moments = compute_moments(blk.polygon);
    blk.material = bd.material;
    blk.dof = bd.fixed ? -1 : unknown_count_++;
    blk.stress = Vector3(bd.initial_stress[0], bd.initial_stress[1], bd.initial_stress[2]);
    if (def.initial_stress) {
      const std::array<double, 3> in_situ = def.initial_stress->at(blk.moments.centroid.y);
      blk.stress += Vector3(in_situ[0], in_situ[1], in_situ[2]);
    }
    blk.velocity << bd.initial_velocity[0], bd.initial_velocity[1], bd.initial_velocity[2], 0,
        0, 0;
    if (bd.fixed) blk.velocity.setZero();
    blk.material_centroid = blk.initial_centroid = blk.moments.centroid;
    if (!bd.edge_joints.empty() && bd.edge_joints.size() != bd.polygon.size())
      throw std::invalid_argument(name + "edge_joints needs one joint type per edge");
    for (int type : bd.edge_joints)
      if (type < 0 || type > static_cast<int>(def.joint_types.size()))
        throw std::invalid_argument(name + "joint type index out of range");
    edge_joints_.push_back(bd.edge_joints);
    for (Point p : blk.polygon) all.add(p);
    blocks_.push_back(std::move(blk));
  }
  const auto check_block = [&](int b) {
    if (b < 0 || b >= block_count()) throw std::invalid_argument("DDA: load on a missing block");
  };
  for (const FixedPoint& f : def.fixed_points) {
    check_block(f.block);
    fixed_points_.push_back({f.block, f.point, f.point});
  }
  for (const PointLoad& l : point_loads_) {
    check_block(l.block);
    if (l.force.columns() != 2) throw std::invalid_argument("DDA: a point load's force needs two columns (fx, fy)");
    load_points_.push_back({l.block, l.point, l.point});
  }
  for (const PrescribedDisplacement& p : displacements_) {
    check_block(p.block);
    if (p.ramp_time <= 0) throw std::invalid_argument("DDA: ramp_time must be > 0");
    displacement_points_.push_back({p.block, p.point, p.point});
  }
  check_tractions(tractions_);
  for (const MeasuredPoint& m : def.measured_points) {
    check_block(m.block);
    measured_.push_back({m.block, m.point, m.point});
  }
  for (const Roller& r : def.rollers) {
    check_block(r.block);
    if (r.vertex < 0 || r.vertex >= static_cast<int>(blocks_[r.block].polygon.size()))
      throw std::invalid_argument("DDA: roller on a missing vertex");
    if (std::abs(geometry::norm(r.normal) - 1.0) > 1e-9) throw std::invalid_argument("DDA: a roller's normal must be a unit vector");
    rollers_.push_back({r, blocks_[r.block].polygon[r.vertex]});
  }
  initial_stress_ = def.initial_stress;
  preload_new_contacts_ = initial_stress_.has_value();
  // Shi's w0: half the model height sets the allowed step displacement.
  model_size_ = 0.5 * std::max(all.height(), 1e-3 * all.width());
  allowed_displacement_ = settings_.max_displacement_ratio * model_size_;
  contact_distance_ = settings_.contact_distance > 0 ? settings_.contact_distance
                                                     : 2.5 * allowed_displacement_;
  penetration_tolerance_ = settings_.penetration_tolerance > 0
                               ? settings_.penetration_tolerance
                               : 1e-4 * allowed_displacement_;
  penalty_ = settings_.penalty > 0 ? settings_.penalty : 50.0 * young_max * 1.0;
  joints_.push_back(strength_of(def.joint));
  for (const Joint& j : def.joint_types) joints_.push_back(strength_of(j));
  for (const JointStrength& j : joints_) broken_joints_.push_back({j.tan_friction, 0.0, 0.0});
  setup_bonds(def.blocks, def.broken_bonds);
  fixed_stiffness_ = 10.0 * penalty_;
  dt_ = settings_.time_step;
  vertex_forces_.resize(blocks_.size());
  // A skin of a fifth of the contact distance keeps the lists for many steps of a slow run
  // and adds little to what each step tests (a wall of 1,601 blocks: 19,000 combinations
  // within the contact distance of 9,400 contacts).
  // Bonded rock keeps a corner's contact at a node of its face while closed, within the
  // penetration tolerance (drop_corner_candidates_not_kept); other models have no such candidate.
  contact_search_ = ContactSearch(contact_distance_,
                                  settings_.contact_skin >= 0 ? settings_.contact_skin : 0.2 * contact_distance_,
                                  bond_sides_.empty() ? kNoCornerMemory : penetration_tolerance_);
  for (const Block& b : blocks_) detection_.fixed.push_back(b.dof < 0);
  if (many_blocks()) numerics::start_threads();
}

void System::check_tractions(std::span<const EdgeTraction> tractions) const {
  for (const EdgeTraction& t : tractions) {
    if (t.block < 0 || t.block >= block_count()) throw std::invalid_argument("DDA: load on a missing block");
    if (t.edge < 0 || t.edge >= static_cast<int>(blocks_[t.block].polygon.size()))
      throw std::invalid_argument("DDA: traction on a missing edge");
  }
}

void System::set_tractions(std::vector<EdgeTraction> tractions) {
  check_tractions(tractions);
  tractions_ = std::move(tractions);
}

void System::set_vertex_forces(std::vector<std::vector<Point>> forces) {
  if (forces.size() != blocks_.size())
    throw std::invalid_argument("DDA: set_vertex_forces needs one list per block");
  for (std::size_t b = 0; b < forces.size(); ++b)
    if (!forces[b].empty() && forces[b].size() != blocks_[b].polygon.size())
      throw std::invalid_argument("DDA: set_vertex_forces needs one force per vertex");
  vertex_forces_ = std::move(forces);
}

Point System::displacement(int block) const {
  return blocks_[block].material_centroid - blocks_[block].initial_centroid;
}

std::array<double, 3> System::stress(int block) const {
  const Vector3& s = blocks_[block].stress;
  return {s[0], s[1], s[2]};
}

std::array<double, 3> System::strain(int block) const {
  const Vector3& s = blocks_[block].strain;
  return {s[0], s[1], s[2]};
}

std::vector<ContactInfo> System::contacts() const {
  std::vector<ContactInfo> out;
  for (const auto& [key, r] : records_) out.push_back({key, r.state, r.penetration, r.normal_force});
  return out;
}

std::vector<System::PrescribedProgress> System::prescribed_progress() const {
  std::vector<PrescribedProgress> out;
  for (std::size_t i = 0; i < displacements_.size(); ++i) {
    const TrackedPoint& tp = displacement_points_[i];
    const double ramp = std::min(1.0, time_ / displacements_[i].ramp_time);
    const Block& b = blocks_[tp.block];
    const double stress = b.stress.cwiseAbs().maxCoeff();
    const double elastic_scale = stress * std::sqrt(b.moments.area) / materials_[b.material].young;
    const Point target = ramp * displacements_[i].value;
    const Point reaction = fixed_stiffness_ * (tp.initial + target - tp.position);
    out.push_back({tp.initial, target, tp.position - tp.initial, elastic_scale, reaction, displacements_[i].entry});
  }
  return out;
}

std::vector<Point> System::measured_positions() const {
  std::vector<Point> out;
  for (const TrackedPoint& m : measured_) out.push_back(m.position);
  return out;
}

// ---- detection and linearisation ----

void System::detect_contacts() {
  DetectionBuffers& buffers = detection_;
  buffers.polygons.clear();
  for (const Block& b : blocks_) buffers.polygons.emplace_back(b.polygon);
  ContactCandidates& candidates = buffers.candidates;
  contact_search_.find(buffers.polygons, buffers.fixed, candidates);
  if (breakable_bonds_ > 0) buffers.before_bond_rules = candidates;
  apply_bond_rules(candidates);
  resize_for_overwrite(active_, candidates.size());
  // The linearisation in chunks of contacts, over the threads: each contact writes only its own.
  numerics::for_each_chunk(many_contacts_to_linearise(), candidates.size(), kContactChunk,
                           [&](std::size_t, std::size_t begin, std::size_t end) {
    if (begin == end) return;
    // Both lists are in key order: one walk finds each candidate's record from the last step.
    auto record = std::lower_bound(records_.begin(), records_.end(), candidates[begin].key,
                                   [](const auto& r, const ContactKey& key) { return r.first < key; });
    for (std::size_t i = begin; i < end; ++i) {
      const ContactCandidate& c = candidates[i];
      ActiveContact& a = active_[i];
      a.key = c.key;
      a.changed_in_step = false;
      a.changed_pass = -1;
      a.pass_penetration = c.penetration;
      while (record != records_.end() && record->first < c.key) ++record;
      if (record != records_.end() && record->first == c.key) {
        a.record = record->second;
      } else {
        a.record = ContactRecord{};
        // Touching (within the hysteresis band) counts as closed: a settled packing starts
        // with its contacts carrying load instead of finding them one open–close pass at a
        // time.
        a.record.state = c.penetration > -1e-2 * penetration_tolerance_ ? closed_state(c.key) : ContactState::open;
        a.record.reference_ratio = c.edge_ratio;
        if (preload_new_contacts_ && is_closed(a.record.state)) preload_contact(a);
      }
      if (a.record.state == ContactState::open) a.record.reference_ratio = c.edge_ratio;
      linearise_contact(a);
      if (is_closed(a.record.state)) linearise_closed_contact(a);
    }
  });
}

void System::relieve_start_loads(FaceShare share) {
  if (!initial_stress_ || time_ != 0.0) return;
  for (RollerPoint& r : rollers_) {
    const Polygon& p = blocks_[r.roller.block].polygon;
    const std::size_t n = p.size();
    const std::array<Point, 2> neighbours{p[(r.roller.vertex + n - 1) % n], p[(r.roller.vertex + 1) % n]};
    r.relief = 0.0;
    for (int k = 0; k < 2; ++k)
      if (r.roller.faces_along[k]) r.relief += share(r.roller.block, p[r.roller.vertex], neighbours[k]);
  }
  start_face_share_ = std::move(share);
}

void System::preload_contact(ActiveContact& c) const {
  const Polygon& pj = blocks_[c.key.block_j].polygon;
  const ContactPreload preload = compute_contact_preload(*initial_stress_, blocks_[c.key.block_i].polygon, c.key.vertex,
                                                         pj, c.key.edge, contact_distance_);
  double normal = preload.normal;
  if (start_face_share_)
    normal -= compute_contact_fluid_push(start_face_share_, c.key.block_i, blocks_[c.key.block_i].polygon, c.key.vertex,
                                         pj, c.key.edge, contact_distance_);
  c.record.multiplier = normal;
  c.record.normal_force = normal;
  // The locked spring pushes block i along the edge by −p s, s = (p1 − p0)·t: a reference
  // point shear/p behind the vertex's projection makes it push by the shear from the start.
  const double length = geometry::distance(pj[c.key.edge], pj[(c.key.edge + 1) % pj.size()]);
  const double stiffness = contact_stiffness(
      c.key, tributary_length(blocks_[c.key.block_i].polygon, c.key.vertex, pj, c.key.edge, contact_distance_));
  c.record.reference_ratio += preload.shear / (stiffness * length);
}

void System::linearise_contact(ActiveContact& c) const {
  const Block& bi = blocks_[c.key.block_i];
  const Block& bj = blocks_[c.key.block_j];
  const int nj = static_cast<int>(bj.polygon.size());
  const Point p1 = bi.polygon[c.key.vertex];
  const Point p2 = bj.polygon[c.key.edge];
  const Point p3 = bj.polygon[(c.key.edge + 1) % nj];
  const double length = geometry::distance(p2, p3);
  // Penetration d = S/L with S = x1(y2−y3) + x2(y3−y1) + x3(y1−y2) twice the signed area
  // of (p1, p2, p3); its first-order change is ∂S/∂pk · Tk D (Shi 1988, eq. 4.12).
  c.penetration0 = geometry::orient(p1, p2, p3) / length;
  const Eigen::RowVector2d g1((p2.y - p3.y) / length, (p3.x - p2.x) / length);
  const Eigen::RowVector2d g2((p3.y - p1.y) / length, (p1.x - p3.x) / length);
  const Eigen::RowVector2d g3((p1.y - p2.y) / length, (p2.x - p1.x) / length);
  c.en_i = (g1 * compute_displacement_matrix(p1, bi.moments.centroid)).transpose();
  c.en_j = (g2 * compute_displacement_matrix(p2, bj.moments.centroid) +
            g3 * compute_displacement_matrix(p3, bj.moments.centroid))
               .transpose();
  c.dof_i = bi.dof;
  c.dof_j = bj.dof;
}

// What only a closed contact uses: the face length it carries and its shear's linearisation.
// Made when the contact is closed at the step's start or closes in one of its passes: the
// blocks stay where the step began until it is committed, so the values are those a
// linearisation of every candidate would have made. Most candidates of a large model stay
// open (in a seal of 10,000 blocks, all of its 370,000), and these were half of their cost.
void System::linearise_closed_contact(ActiveContact& c) const {
  const Polygon& pi = blocks_[c.key.block_i].polygon;
  const Polygon& pj = blocks_[c.key.block_j].polygon;
  c.length = tributary_length(pi, c.key.vertex, pj, c.key.edge, contact_distance_);
  c.stiffness = contact_stiffness(c.key, c.length);
  const int nj = static_cast<int>(pj.size());
  const Point p1 = pi[c.key.vertex];
  const Point p2 = pj[c.key.edge];
  const Point p3 = pj[(c.key.edge + 1) % nj];
  const Point s = (p3 - p2) / geometry::distance(p2, p3);
  // Shear: s = (p1 − p0)·t, p0 the reference point on the edge, moving with block j.
  const Point p0 = p2 + c.record.reference_ratio * (p3 - p2);
  const Eigen::RowVector2d t(s.x, s.y);
  c.shear0 = dot(p1 - p0, s);
  c.es_i = (t * compute_displacement_matrix(p1, blocks_[c.key.block_i].moments.centroid)).transpose();
  c.es_j = -(t * compute_displacement_matrix(p0, blocks_[c.key.block_j].moments.centroid)).transpose();
}

// ---- assembly ----

void System::assemble_blocks(double dt, Matrix6Array& k, Eigen::VectorXd& f_base) const {
  f_base = Eigen::VectorXd::Zero(6 * unknown_count_);
  k.assign(unknown_count_, Matrix6::Zero());
  const bool dynamic = settings_.analysis == Analysis::dynamic;
  const auto add_spring = [&](int block, Point at, Point target_displacement) {
    const Block& b = blocks_[block];
    if (b.dof < 0) return;
    const Matrix26 t = compute_displacement_matrix(at, b.moments.centroid);
    // ½ k |T D − u*|²: stiffness k TᵀT, load k Tᵀ u*.
    k[b.dof] += fixed_stiffness_ * t.transpose() * t;
    f_base.segment<6>(6 * b.dof) +=
        fixed_stiffness_ * t.transpose() * Eigen::Vector2d(target_displacement.x, target_displacement.y);
  };
  // Each block writes only its own rows.
  numerics::for_each_index(many_blocks(), blocks_.size(), [&](std::size_t bi) {
    const Block& b = blocks_[bi];
    if (b.dof < 0) return;
    const Material& mat = materials_[b.material];
    const Moments& m = b.moments;
    Matrix6& kb = k[b.dof];
    auto fb = f_base.segment<6>(6 * b.dof);
    // Elastic strain energy: A·E on the strains.
    kb += compute_elastic_stiffness(m, elasticity_[b.material]);
    // Initial (accumulated) stress: −A σ on the strains.
    fb.segment<3>(3) -= m.area * b.stress;
    // Body force: ρ A g on the translations (∫T dA has only those about the centroid).
    fb[0] += mat.density * m.area * settings_.gravity.x;
    fb[1] += mat.density * m.area * settings_.gravity.y;
    // Inertia: d = vΔt + aΔt²/2 gives 2M/Δt² in K and 2M v/Δt in F.
    const Matrix6 mass = compute_mass_matrix(m, mat.density);
    kb += 2.0 / (dt * dt) * mass;
    if (dynamic) fb += 2.0 / dt * mass * b.velocity;
  });
  for (const TrackedPoint& f : fixed_points_) add_spring(f.block, f.position, f.initial - f.position);
  for (std::size_t i = 0; i < displacements_.size(); ++i) {
    const PrescribedDisplacement& p = displacements_[i];
    const TrackedPoint& tp = displacement_points_[i];
    const double ramp = std::min(1.0, (time_ + dt) / p.ramp_time);
    add_spring(tp.block, tp.position, tp.initial + ramp * p.value - tp.position);
  }
  for (const RollerPoint& r : rollers_) {
    const Block& b = blocks_[r.roller.block];
    if (b.dof < 0) continue;
    const Point at = b.polygon[r.roller.vertex];
    const Point n = r.roller.normal;
    // ½ k (n·(x − x_initial + T D) + preload/k)², a spring along the normal only: stiffness
    // k w wᵀ and load −w (k n·(x − x_initial) + preload), w = Tᵀ n. At the start it pushes the
    // vertex in (along −n) by the preload.
    const Vector6 w = compute_displacement_matrix(at, b.moments.centroid).transpose() * Eigen::Vector2d(n.x, n.y);
    k[b.dof] += fixed_stiffness_ * w * w.transpose();
    f_base.segment<6>(6 * b.dof) -= w * (fixed_stiffness_ * dot(n, at - r.initial) + r.roller.preload - r.relief);
  }
  // Loads given as time tables at the end of the step (the implicit step's equilibrium), or
  // at the held load time.
  const double load_time = held_load_time_.value_or(time_ + dt);
  for (std::size_t i = 0; i < point_loads_.size(); ++i) {
    const Block& b = blocks_[load_points_[i].block];
    if (b.dof < 0) continue;
    const Matrix26 t = compute_displacement_matrix(load_points_[i].position, b.moments.centroid);
    const numerics::TimeTable& force = point_loads_[i].force;
    f_base.segment<6>(6 * b.dof) += t.transpose() * Eigen::Vector2d(force.value(load_time, 0), force.value(load_time, 1));
  }
  for (const EdgeTraction& tr : tractions_) {
    const Block& b = blocks_[tr.block];
    if (b.dof < 0) continue;
    const int n = static_cast<int>(b.polygon.size());
    f_base.segment<6>(6 * b.dof) += compute_edge_traction_load(
        b.polygon[tr.edge], b.polygon[(tr.edge + 1) % n], b.moments.centroid, tr.normal_start.value(load_time),
        tr.normal_end.value(load_time), tr.shear_start.value(load_time), tr.shear_end.value(load_time));
  }
  for (std::size_t bi = 0; bi < blocks_.size(); ++bi) {
    const Block& b = blocks_[bi];
    if (b.dof < 0 || vertex_forces_[bi].empty()) continue;
    for (std::size_t v = 0; v < b.polygon.size(); ++v) {
      const Point f = vertex_forces_[bi][v];
      f_base.segment<6>(6 * b.dof) += compute_displacement_matrix(b.polygon[v], b.moments.centroid)
                                          .transpose() * Eigen::Vector2d(f.x, f.y);
    }
  }
}

void System::factor_with_contacts() {
  // The matrix is the blocks' own terms (assembly_.matrix, diagonal, made once a step) plus
  // one penalty spring w wᵀ per closed contact, normal and, locked, shear: w = √p e, e the
  // contact's row of the linearised penetration or shear. The springs stay rank-one terms:
  // the solver multiplies by them and assembles them only when it factors, and follows those
  // that come and go between passes. The solver reads the springs where they are, and the
  // next pass writes its own over them: fresh memory costs more in page faults than the
  // assembly itself.
  RankOneTerms& terms = assembly_.terms;
  // A normal spring for each closed contact, a shear one for each locked, and the closed
  // contacts listed (closed_: the pass's loops over contacts that carry load walk that list,
  // not every candidate); each half of the contacts writes its springs and its list entries
  // from where the chunks before it end.
  struct Counts {
    std::size_t springs = 0, closed = 0;
  };
  const auto counts = numerics::results_in_chunks(many_contacts(), active_.size(), kContactChunk,
                                                  [&](std::size_t begin, std::size_t end) {
    Counts count;
    for (std::size_t i = begin; i < end; ++i) {
      const ContactState state = active_[i].record.state;
      count.closed += is_closed(state) ? 1 : 0;
      count.springs += (is_closed(state) ? 1 : 0) + (state == ContactState::locked ? 1 : 0);
    }
    return count;
  });
  std::vector<Counts> starts(counts.size());  // where each chunk's springs and entries go
  Counts total;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    starts[k] = total;
    total.springs += counts[k].springs;
    total.closed += counts[k].closed;
  }
  resize_for_overwrite(terms, total.springs);
  resize_for_overwrite(closed_, total.closed);
  numerics::for_each_chunk(many_contacts(), active_.size(), kContactChunk,
                           [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    RankOneTerm* next = terms.data() + starts[chunk].springs;
    int* next_closed = closed_.data() + starts[chunk].closed;
    const auto add_term = [&](const ActiveContact& c, int kind, const Vector6& e_i, const Vector6& e_j, double penalty) {
      const ContactKey& k = c.key;
      RankOneTerm& t = *next++;
      t.id = {k.block_i, k.vertex, k.block_j, k.edge, kind};
      t.block_a = c.dof_i;
      t.block_b = c.dof_j;
      const double root_stiffness = std::sqrt(penalty);
      t.w_a = root_stiffness * e_i;
      t.w_b = root_stiffness * e_j;
    };
    // active_ is in key order, and so the terms in id order.
    for (std::size_t i = begin; i < end; ++i) {
      ActiveContact& c = active_[i];
      if (!is_closed(c.record.state)) continue;
      *next_closed++ = static_cast<int>(i);
      c.normal_stiffness = normal_spring(c);
      add_term(c, 0, c.en_i, c.en_j, c.normal_stiffness);  // normal spring ½ p d²
      if (c.record.state == ContactState::locked) add_term(c, 1, c.es_i, c.es_j, c.stiffness);  // shear ½ p s²
    }
  });
  // Both stay as they are through this pass's solves; the next step's assembly writes over
  // the matrix only before its own first call.
  solver_->factor_borrowing(assembly_.matrix, terms);
}

Eigen::VectorXd System::assemble_contact_rhs(const Eigen::VectorXd& f_base) const {
  Eigen::VectorXd f = f_base;
  if (!many_closed_contacts()) {
    add_contact_loads(0, closed_.size(), f);
    return f;
  }
  // The halves of the contacts load the same blocks: each adds into its own vector, the
  // second's added to the first's after.
  Eigen::VectorXd second = Eigen::VectorXd::Zero(f_base.size());
  numerics::run_two_parts(true, [&](int part) {
    const auto [begin, end] = numerics::half_range(part, closed_.size());
    add_contact_loads(begin, end, part == 0 ? f : second);
  });
  f += second;
  return f;
}

void System::add_contact_loads(std::size_t begin, std::size_t end, Eigen::VectorXd& f) const {
  for (std::size_t k = begin; k < end; ++k) {
    const ActiveContact& c = active_[closed_[k]];
    const ContactRecord& r = c.record;
    // Normal: energy λ d + ½ p d² → load −(λ + p d0) en.
    const double normal = r.multiplier + c.normal_stiffness * c.penetration0;
    add_segment(f, c.dof_i, -normal * c.en_i);
    add_segment(f, c.dof_j, -normal * c.en_j);
    if (r.state == ContactState::locked) {
      add_segment(f, c.dof_i, -c.stiffness * c.shear0 * c.es_i);
      add_segment(f, c.dof_j, -c.stiffness * c.shear0 * c.es_j);
    } else {
      // Sliding: Mohr–Coulomb friction f = N tan φ + c l against the sliding direction.
      const JointStrength& joint = joint_of(c.key);
      const double friction =
          (std::max(r.normal_force, 0.0) * joint.tan_friction + joint.cohesion * c.length) * r.slide_sign;
      add_segment(f, c.dof_i, -friction * c.es_i);
      add_segment(f, c.dof_j, -friction * c.es_j);
    }
  }
}

Eigen::VectorXd System::friction_load_change(const std::vector<ActiveContact*>& sliding,
                                             const Eigen::VectorXd& from, const Eigen::VectorXd& to) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * unknown_count_);
  for (std::size_t k = 0; k < sliding.size(); ++k) {
    const ActiveContact& c = *sliding[k];
    // The friction load −(N tan φ + c l) s es of assemble_contact_rhs, from N = from to N = to.
    const double change = (std::max(to[static_cast<Eigen::Index>(k)], 0.0) -
                           std::max(from[static_cast<Eigen::Index>(k)], 0.0)) *
                          joint_of(c.key).tan_friction * c.record.slide_sign;
    add_segment(f, c.dof_i, -change * c.es_i);
    add_segment(f, c.dof_j, -change * c.es_j);
  }
  return f;
}

Vector6 System::block_unknowns(const Eigen::VectorXd& d, int dof) const {
  return dof < 0 ? Vector6::Zero() : Vector6(d.segment<6>(6 * dof));
}

namespace {

// e · D for a block's unknowns D in d (zero for a block without unknowns), read in place: every
// open–close pass takes it twice or thrice for every contact. The same sum as with D copied out.
double dot_with_block(const Vector6& e, const Eigen::VectorXd& d, int dof) {
  return dof < 0 ? e.dot(Vector6::Zero()) : e.dot(d.segment<6>(6 * dof));
}

}  // namespace

double System::compute_penetration(const ActiveContact& c, const Eigen::VectorXd& d) const {
  return c.penetration0 + dot_with_block(c.en_i, d, c.dof_i) + dot_with_block(c.en_j, d, c.dof_j);
}

double System::compute_shear(const ActiveContact& c, const Eigen::VectorXd& d) const {
  return c.shear0 + dot_with_block(c.es_i, d, c.dof_i) + dot_with_block(c.es_j, d, c.dof_j);
}

double System::compute_normal_force(const ActiveContact& c, double penetration) const {
  return c.record.multiplier + c.normal_stiffness * penetration;
}

double System::compute_shear_strength(const ActiveContact& c, double normal_force) const {
  const JointStrength& joint = joint_of(c.key);
  return std::max(normal_force, 0.0) * joint.tan_friction + joint.cohesion * c.length;
}

// A locked contact on a frictionless, cohesionless joint would hold a shear of up to p × its
// shear band (update_state) that the joint cannot carry, slide once that is passed, and lock
// again at the next reversal: across the passes of a coupled step, the strips of Mandel's
// problem pulled under their frictionless plate flipped locked ↔ sliding at every corner and
// the step's iterations cycled (docs/studies/2026-11-29-mandel-first-attempt.md). Such a
// contact slides from the moment it closes, its friction N tan φ + c l = 0.
ContactState System::closed_state(const ContactKey& key) const {
  if (is_intact_bond(key)) return ContactState::locked;
  const JointStrength& joint = joint_of(key);
  return joint.tan_friction == 0.0 && joint.cohesion == 0.0 ? ContactState::sliding : ContactState::locked;
}

System::ContactForceExtent System::update_contact_forces(const Eigen::VectorXd& d) {
  // Largest values: the same whatever the chunks.
  const auto chunks = numerics::results_in_chunks(many_closed_contacts(), closed_.size(), kContactChunk,
                                                  [&](std::size_t begin, std::size_t end) {
    ContactForceExtent extent;
    for (std::size_t k = begin; k < end; ++k) {
      ActiveContact& c = active_[closed_[k]];
      const double pen = compute_penetration(c, d);
      const double normal = compute_normal_force(c, pen);
      extent.deepest = std::max(extent.deepest, std::abs(pen));
      extent.force_scale = std::max(extent.force_scale, std::abs(normal));
      c.record.normal_force = normal;
      c.record.penetration = pen;
    }
    return extent;
  });
  ContactForceExtent all;
  for (const ContactForceExtent& chunk : chunks) {
    all.deepest = std::max(all.deepest, chunk.deepest);
    all.force_scale = std::max(all.force_scale, chunk.force_scale);
  }
  return all;
}

double System::largest_vertex_motion(const Eigen::VectorXd& change) const {
  const auto largest = numerics::results_in_chunks(many_blocks(), blocks_.size(), kBlockChunk,
                                                   [&](std::size_t begin, std::size_t end) {
    double chunk_largest = 0.0;  // squared: one square root at the end
    for (std::size_t bi = begin; bi < end; ++bi) {
      const Block& b = blocks_[bi];
      if (b.dof < 0) continue;
      const Vector6 db = change.segment<6>(6 * b.dof);
      for (Point p : b.polygon) {
        const Point moved = first_order_displacement(p, b.moments.centroid, db);
        chunk_largest = std::max(chunk_largest, moved.x * moved.x + moved.y * moved.y);
      }
    }
    return chunk_largest;
  });
  return std::sqrt(largest.empty() ? 0.0 : *std::max_element(largest.begin(), largest.end()));
}

// Moves contact c to the state the solution d puts it in: open ↔ closed by penetration and
// tension, locked ↔ sliding by Mohr–Coulomb, with hysteresis `band`. Whether it changed.
// A closed contact opens when its normal force N = λ + p d falls below −T l − allowance
// (T the tensile strength, l the face length the contact carries).
//
// Tension cutoff (Settings::tension_cutoff; Shi 1988: contacts take no tension beyond the
// joint's strength; the tension cutoff of UDEC's Coulomb slip joint, Itasca): the allowance
// is 1e-9 N_max (N_max the largest normal force of the pass: round-off, not a band), and the
// pass is solved again without the contacts it opened, so that no accepted step leaves a
// closed contact pulling harder than T l. The hysteresis that keeps a contact from flipping
// on round-off then lies on the other side, in length: an open contact closes when it
// penetrates past `band`, and one the cutoff opened (ContactRecord::released) only when it
// penetrates past the penetration tolerance. The augmented Lagrangian leaves a closed contact
// anywhere within the tolerance of touching, so a contact released from a small pull with its
// vertex a little inside the edge would otherwise close again at the next pass, pull again
// once its multiplier had caught up, and flip on until the step were cut. The mark is kept
// from step to step until the contact parts by more than the tolerance (commit_step): a wall
// settling under its weight brings such a contact back within the band in a later step, and
// the joints its cutoff had opened closed again by the dozen a step, each to be opened again
// a pass or two later (docs/studies/2026-11-29-wall-chatter-across-steps.md). Without the
// cutoff the allowance is p × band, the force of the band's length on the penalty spring.
//
// A closed contact on an intact bond (is_intact_bond) stays locked: its face breaks as a whole
// (break_overloaded_bonds), after which it is a joint's contact like any other.
bool System::update_state(ActiveContact& c, const Eigen::VectorXd& d, double band, double tension_allowance) const {
  ContactRecord& r = c.record;
  const double pen = compute_penetration(c, d);
  // Kept for the commit: the pass that changes no state is the step's last, and its d the
  // one committed (a closed contact's is the value update_contact_forces set from that d).
  r.penetration = pen;
  if (r.state == ContactState::open) {
    if (pen > (r.released ? std::max(band, penetration_tolerance_) : band)) {
      r.state = closed_state(c.key);
      r.multiplier = 0.0;
      r.released = false;
      linearise_closed_contact(c);
      return true;
    }
    return false;
  }
  if (is_intact_bond(c.key)) return false;
  const double normal = compute_normal_force(c, pen);
  if (normal < -joint_of(c.key).tensile_strength * c.length - tension_allowance) {
    r.state = ContactState::open;
    r.multiplier = 0.0;
    r.normal_force = 0.0;
    r.released = settings_.tension_cutoff;
    return true;
  }
  // Narrower for slip than for a reversal: a locked spring stretches only F/p.
  const double shear_band = 0.1 * band;
  const double shear = compute_shear(c, d);
  if (r.state == ContactState::locked) {
    if (c.stiffness * (std::abs(shear) - shear_band) > compute_shear_strength(c, normal)) {
      r.state = ContactState::sliding;
      r.slide_sign = shear > 0 ? 1 : -1;
      return true;
    }
  } else if (shear * r.slide_sign < -band && closed_state(c.key) == ContactState::locked) {  // a clear reversal only
    r.state = ContactState::locked;
    return true;
  }
  return false;
}

// ---- open–close iteration ----

// Pseudocode (Shi 1988 §5; Lin 1995 for the multipliers):
//   repeat (open–close) until no contact changes state:
//     factor K(states)
//     repeat (Lagrangian): solve K D = F(λ, friction); λ ← λ + p d on closed contacts
//       until every closed penetration < tolerance and the friction loads settle
//       (the sliding contacts' normal forces, a fixed point mixed by Anderson acceleration:
//       settled when they change by less than 1e-6 of the largest normal force, or when the
//       last friction update, or change of states, moved no vertex by more than 1% of the
//       penetration tolerance)
//     re-check each contact: open ↔ closed by penetration / tension, locked ↔ sliding by
//     Mohr–Coulomb
//   not settled in max iterations (states or forces) → the caller cuts Δt and retries.
System::Unsettled System::solve_step(double dt, Eigen::VectorXd& d, StepReport& report) {
  // The blocks' own terms: the same for every pass of the step.
  BlockMatrix& base = assembly_.matrix;
  base.block_count = unknown_count_;
  base.pairs.clear();
  base.off.clear();
  Eigen::VectorXd f_base;
  assemble_blocks(dt, base.diagonal, f_base);
  const bool lagrangian = settings_.contact == ContactMethod::augmented_lagrangian;
  // The solution before the last friction update or the last change of states, to measure
  // what the update moved.
  Eigen::VectorXd before_friction_update;
  // Whether the last pass's loads settled within two solves (taken for granted in the first).
  bool settled_at_once = true;
  // The largest normal force of the pass's accepted solution (for the tension cutoff).
  double force_scale = 0.0;
  // Passes in which some contact changed state a second time in this step: the step is cut
  // after max_open_close_iterations of them (see below), or after four times as many passes
  // and one more for each pass that broke a bond.
  int passes_without_progress = 0;
  // Passes that broke a bond lengthen the cap by one each: a bond breaks once in a try, so
  // there are at most 4 × max_open_close_iterations + (the bonds intact at the try's start).
  int passes_breaking_bonds = 0;
  const int pass_cap = 4 * settings_.max_open_close_iterations;
  // Passes whose softening bonds' cohesive loads moved lengthen it too: they are bounded by
  // the crack's running, which breaks a bond after a few of them (softening_bonds.cpp).
  int passes_settling_cohesion = 0;
  Eigen::VectorXd f_pass;  // f_base and the softening bonds' cohesive loads
  open_close_pass_ = -1;
  for (int oc = 0; oc < pass_cap + passes_breaking_bonds + passes_settling_cohesion &&
                   passes_without_progress < settings_.max_open_close_iterations;
       ++oc) {
    if (interrupt_check_ && interrupt_check_()) return Unsettled::interrupted;
    report.open_close_iterations = oc + 1;
    open_close_pass_ = oc;
    // Softening bonds' cohesive tractions, from the opening of the last pass (the step's start
    // in the first): loads on their faces (softening_bonds.cpp).
    if (!softening_.empty()) {
      f_pass = f_base;
      add_cohesive_loads(oc == 0 ? Eigen::VectorXd() : d, f_pass);
    }
    const Eigen::VectorXd& f_loads = softening_.empty() ? f_base : f_pass;
    factor_with_contacts();
    pass_start_multipliers_.resize(closed_.size());
    for (std::size_t k = 0; k < closed_.size(); ++k) pass_start_multipliers_[k] = active_[closed_[k]].record.multiplier;
    // The sliding contacts' normal forces: those the friction loads were made with (x) and
    // those the solution gives (G(x)).
    std::vector<ActiveContact*> sliding;
    for (int i : closed_)
      if (active_[i].record.state == ContactState::sliding) sliding.push_back(&active_[i]);
    Eigen::VectorXd used(sliding.size());
    Eigen::VectorXd image(sliding.size());
    numerics::AndersonAccelerator friction_mixing;
    numerics::AndersonAccelerator multiplier_mixing;
    char opened_standing_off = 0;  // as a pass's changes of state below
    Eigen::VectorXd last_pass;     // the solution of the try's last pass but one
    for (int al = 0; al < lagrangian_limit_; ++al) {
      ++report.lagrangian_iterations;
      for (std::size_t k = 0; k < sliding.size(); ++k) used[k] = sliding[k]->record.normal_force;
      if (al > 0 && al + 1 == lagrangian_limit_) last_pass = d;
      // Multipliers that grew without bound (a pass's solution far past the allowed step,
      // λ ← λ + p d amplifying it pass after pass) leave nothing to solve: the try is cut.
      // Loads not finite before any contact (a mass that overflows) are the model's: the
      // solver names them, and no shorter step would mend them.
      const Eigen::VectorXd rhs = assemble_contact_rhs(f_loads);
      if (!std::isfinite(rhs.norm()) && std::isfinite(f_loads.norm())) {
        unsettled_forces_ = "the contact forces grew without bound";
        return Unsettled::contact_forces;
      }
      d = solver_->solve(rhs);
      // A solve that moves a vertex farther than half the model's height (Shi's w0, of which a
      // kept step may move one max_displacement_ratio) has thrown blocks: a sub-block freed of
      // its bonds, held along its slip by its inertia alone, flung by its contact's friction.
      // No step that far can be kept, and the multipliers and frictions learnt from it would
      // carry it into every later solve of the try: the try ends, and the step is cut.
      if (const double motion = largest_vertex_motion(d); motion > model_size_) {
        thrown_motion_ = motion;
        return Unsettled::thrown;
      }
      ContactForceExtent extent = update_contact_forces(d);
      for (std::size_t k = 0; k < sliding.size(); ++k) image[k] = sliding[k]->record.normal_force;
      const double friction_change = sliding.empty() ? 0.0 : (image - used).lpNorm<Eigen::Infinity>();
      bool penetration_ok = !lagrangian || extent.deepest <= penetration_tolerance_;
      // A friction update that no longer moves the blocks by a measurable amount (1% of the
      // penetration tolerance, the length the step resolves) has settled the loads even if
      // the forces still differ: iterating on would change the solution by less.
      const double settled_motion = 1e-2 * penetration_tolerance_;
      double last_update_motion = std::numeric_limits<double>::infinity();
      bool friction_ok = friction_change <= 1e-6 * extent.force_scale;
      if (!friction_ok && before_friction_update.size() == d.size()) {
        last_update_motion = largest_vertex_motion(d - before_friction_update);
        friction_ok = last_update_motion <= settled_motion;
      }
      // The next update's motion, without solving again: the solution for the change of the
      // friction loads alone, to 1% of itself (a preconditioned iteration or two where a solve
      // takes several from a residual of 1e-12). Small, it is that last update: added, it gives
      // the solution the update would, to 1% of a motion already too small to count. Worth an
      // estimate where it is likely to be small: the last update moved the blocks little
      // (within 4× the settled motion, about two estimates in three are then small enough on a
      // settling packing), or, first in a pass, the loads settled at once in the pass before.
      const bool promising = al == 0 ? settled_at_once : last_update_motion <= 4.0 * settled_motion;
      if (penetration_ok && !friction_ok && promising) {
        const Eigen::VectorXd update = solver_->estimate(friction_load_change(sliding, used, image), 1e-2);
        if (largest_vertex_motion(update) <= settled_motion) {
          d += update;
          extent = update_contact_forces(d);
          penetration_ok = !lagrangian || extent.deepest <= penetration_tolerance_;
          friction_ok = true;
        }
      }
      if (penetration_ok && friction_ok) {
        settled_at_once = al <= 1;
        force_scale = extent.force_scale;
        break;
      }
      // Forces that have not settled are no solution to accept: the step is cut and retried.
      if (al + 1 == lagrangian_limit_) {
        // Passes that no longer move the blocks changed only multipliers: those of the contacts
        // already within the tolerance are taken back (lagrangian_limits.cpp).
        const bool stalled = !penetration_ok && last_pass.size() == d.size() &&
                             largest_vertex_motion(d - last_pass) <= settled_motion;
        if (stalled) extent = undo_stalled_updates_within_tolerance(d);
        // Unless a closed contact stands off its edge: it opens (lagrangian_limits.cpp).
        if (!penetration_ok) opened_standing_off = open_contacts_standing_off();
        if (opened_standing_off) break;
        // Or the passes no longer move the blocks and no overlap grew (lagrangian_limits.cpp).
        if (stalled && overlaps_held(1.0)) {
          settled_at_once = false;
          force_scale = extent.force_scale;
          break;
        }
        // Its multipliers go on to the next try if every overlap is at the tolerance.
        if (stalled && overlaps_held(2.0)) keep_tried_multipliers();
        unsettled_forces_ = describe_unsettled_forces(penetration_ok, friction_change, extent.force_scale);
        return Unsettled::contact_forces;
      }
      if (!penetration_ok) {
        update_multipliers(al, multiplier_mixing);
        friction_mixing.reset();  // a new map: its history no longer applies
        before_friction_update.resize(0);
      } else {
        multiplier_mixing.reset();
        before_friction_update = d;
        const Eigen::VectorXd mixed = friction_mixing.next(used, image);
        for (std::size_t k = 0; k < sliding.size(); ++k) sliding[k]->record.normal_force = mixed[k];
      }
    }
    if (opened_standing_off) {
      // The other contacts' states are judged on the next pass's solution: this one did not settle.
      if (opened_standing_off & 2) ++passes_without_progress;
      before_friction_update.resize(0);
      continue;
    }
    // Hysteresis bands (1% of the penetration tolerance) keep a contact that merely touches,
    // or a joint under no load, from flipping state on round-off. A closed joint set carrying
    // next to no load (the joints of a flexed layer) can flip open and shut on its elastic
    // deformation (~1e-7 m) from one pass to the next; when a quarter of the passes have gone
    // by without settling, the bands widen tenfold rather than the step being cut a
    // thousandfold to settle them. They stay well inside the penetration tolerance either way.
    const bool chattering = oc >= settings_.max_open_close_iterations / 4;
    const double band = (chattering ? 1e-1 : 1e-2) * penetration_tolerance_;
    // The tension a closed contact may carry past T l: round-off with the tension cutoff, else
    // the force of the band's length on the penalty spring.
    const double tension_allowance = settings_.tension_cutoff ? 1e-9 * force_scale : penalty_ * band;
    const auto changed = numerics::results_in_chunks(many_contacts(), active_.size(), kContactChunk,
                                                     [&](std::size_t begin, std::size_t end) {
      // Bit 1: some contact changed; bit 2: some contact changed for the second time in this step.
      char seen = 0;  // char, not bool: vector<bool>'s elements share bytes between threads
      for (std::size_t i = begin; i < end; ++i) {
        ActiveContact& c = active_[i];
        const ContactState from = c.record.state;
        const double penetration_from = c.pass_penetration;
        const bool changed = update_state(c, d, band, tension_allowance);
        c.pass_penetration = c.record.penetration;
        if (!changed) continue;
        note_state_change(c, oc, from, penetration_from);
        seen |= c.changed_in_step ? 3 : 1;
        c.changed_in_step = true;
      }
      return seen;
    });
    // A bond whose face the solution overloads breaks before the next pass, which then opens
    // or slides its contacts as a joint's: a change of state like a contact's.
    // Softening bonds: a pass whose opening moved their tractions from those its loads were
    // made with is no solution yet, and one that opened a face past w_c broke its bond.
    const bool contacts_changed = std::any_of(changed.begin(), changed.end(), [](char c) { return c != 0; });
    const CohesionChange cohesion =
        softening_.empty() ? CohesionChange::none : settle_cohesive_loads(d, contacts_changed);
    const bool bonds_broke =
        (!bond_sides_.empty() && break_overloaded_bonds(d)) || cohesion == CohesionChange::broke;
    if (!bonds_broke && cohesion == CohesionChange::none && !contacts_changed) return Unsettled::no;
    // A pass that changed only contacts that had kept their state all step is progress: the
    // cutoff opening, pass by pass, the joints that its earlier openings left pulling (a
    // 1,601-block wall's first step: 2,725 of them, then 697, 93, 45, ..., 2), which ends, as
    // each contact so changes once. A shorter step would start the same cascade again; only
    // passes in which a contact changes back, or on, count towards cutting the step.
    // A pass that broke a bond is progress too, whatever its contacts did: as a crack runs, the
    // contacts about the faces that broke open and close again while the load moves on to the
    // next faces (across the Brazilian disc at D/40: 50 bonds in 13 passes, contacts changing
    // back in every one). Counted, they cut the step until it broke nothing, and the run crept
    // in ever-shorter steps towards the load at which the crack starts, never passing it.
    if (cohesion == CohesionChange::moved) ++passes_settling_cohesion;
    if (bonds_broke)
      ++passes_breaking_bonds;
    else if (std::any_of(changed.begin(), changed.end(), [](char c) { return (c & 2) != 0; }))
      ++passes_without_progress;
    // A pass whose states changed leaves its friction loads settled for the states it had; a
    // few contacts that change state at the margin of Mohr–Coulomb (slip starting at a
    // shear force a hair above the strength) hardly move the blocks, so the next pass's
    // first solve, measured against this one, can show the loads still settled.
    before_friction_update = d;
  }
  unsettled_states_ = describe_unsettled_states(open_close_pass_);
  return Unsettled::contact_states;
}

// Where the augmented Lagrangian stopped short: the closed contact farthest from touching
// (overlapping, or standing off its edge while closed) against the penetration tolerance, or,
// with every contact within it, how far the sliding contacts' normal forces still moved.
std::string System::describe_unsettled_forces(bool penetration_ok, double friction_change, double force_scale) const {
  if (penetration_ok)
    return "the sliding contacts' normal forces still changed by " + format_number(friction_change) + " N/m (" +
           format_number(friction_change / std::max(force_scale, 1e-300)) + " of the largest contact force)";
  const ActiveContact* deepest = nullptr;
  for (int i : closed_)
    if (!deepest || std::abs(active_[i].record.penetration) > std::abs(deepest->record.penetration)) deepest = &active_[i];
  if (!deepest) return "no closed contact";
  const ContactKey& k = deepest->key;
  const Point at = blocks_[k.block_i].polygon[k.vertex];
  const double pen = deepest->record.penetration;
  return "the farthest from touching, vertex " + std::to_string(k.vertex) + " of block " + std::to_string(k.block_i) +
         " against edge " + std::to_string(k.edge) + " of block " + std::to_string(k.block_j) + " at (" +
         format_number(at.x) + ", " + format_number(at.y) + "), " + (pen > 0 ? "overlaps it by " : "stands off it by ") +
         format_number(std::abs(pen)) + " m, against a penetration tolerance of " +
         format_number(penetration_tolerance_) + " m";
}

// ---- the step ----

void System::release_step_buffers() {
  std::vector<ActiveContact>().swap(active_);
  std::vector<int>().swap(closed_);
}

StepReport System::step() {
  StepReport report;
  dt_ = std::min(settings_.time_step, dt_);
  lagrangian_limit_ = settings_.max_lagrangian_iterations;
  mixing_multipliers_ = false;
  stiff_normal_springs_ = false;
  const double first_time_step = dt_;
  std::string first_failure;
  tried_multipliers_.clear();
  // The bonds broken by a settled try that ran a corner into a block where their breaking
  // freed a contact (breaks_let_corners_in): the step is tried again at the same time step
  // with them broken from its start.
  std::vector<std::pair<int, BondFailure>> broken_from_start;
  for (;;) {
    if (broken_from_start.empty()) {
      report.most_breaks_in_a_cut_try = std::max(report.most_breaks_in_a_cut_try, static_cast<int>(pending_breaks_.size()));
      if (!pending_breaks_.empty()) last_cut_try_breaks_ = pending_breaks_;
    }
    undo_pending_bond_breaks();  // a retried step breaks its bonds anew
    for (const auto& [bond, mode] : broken_from_start) {
      bond_broken_[static_cast<std::size_t>(bond)] = 1;
      pending_breaks_.emplace_back(bond, mode);
    }
    detect_contacts();
    start_from_tried_multipliers();  // those of a try stalled at the tolerance (lagrangian_limits.cpp)
    tried_multipliers_.clear();
    Eigen::VectorXd d;
    const Unsettled unsettled = solve_step(dt_, d, report);
    if (unsettled == Unsettled::interrupted) abandon_interrupted_step(first_time_step, report);
    const bool settled = unsettled == Unsettled::no;
    double largest = 0.0;
    int largest_block = -1;
    if (settled) {
      for (std::size_t bi = 0; bi < blocks_.size(); ++bi) {
        const Block& b = blocks_[bi];
        if (b.dof < 0) continue;
        const BlockMotion motion(b.moments.centroid, d.segment<6>(6 * b.dof));
        for (Point p : b.polygon) {
          const double moved = geometry::distance(p, motion(p));
          if (moved > largest || !std::isfinite(moved)) largest_block = static_cast<int>(bi);
          largest = std::max(largest, moved);
        }
      }
    }
    const bool kept = settled && largest <= allowed_displacement_;
    if (kept && softening_.empty() && breaks_let_corners_in(d)) {
      broken_from_start = pending_breaks_;
      ++report.tries_with_bonds_broken;
      continue;
    }
    broken_from_start.clear();
    if (kept) {
      report.max_displacement = largest;
      contact_search_.add_motion(largest);
      measure_free_drift(d, report);
      std::vector<Point> translation(blocks_.size());
      for (std::size_t bi = 0; bi < blocks_.size(); ++bi)
        if (blocks_[bi].dof >= 0) translation[bi] = {d[6 * blocks_[bi].dof], d[6 * blocks_[bi].dof + 1]};
      commit_step(d, dt_);
      record_pending_bond_breaks();
      measure_unbalanced_force(translation, dt_, report);
      break;
    }
    const std::string why =
        settled ? "block " + std::to_string(largest_block) + " still moved " + format_number(largest) +
                      " m in a step, more than the allowed " + format_number(allowed_displacement_) + " m"
        : unsettled == Unsettled::thrown
            ? "a solve of its open-close passes threw blocks, moving a vertex by " + format_number(thrown_motion_) +
                  " m, farther than half the model's height (" + format_number(model_size_) + " m)"
        : unsettled == Unsettled::contact_states
            ? "the open-close iteration did not settle the contact states: " + unsettled_states_
            : "the contact forces (Lagrange multipliers and friction) did not settle in " +
                  std::to_string(lagrangian_limit_) + (lagrangian_limit_ == 1 ? " pass: " : " passes: ") +
                  unsettled_forces_;
    // What failed at the step's first try, before cuts changed the problem (a tiny step's
    // inertia holds every overlap where it stands), is said too when the last cut failed otherwise.
    if (report.retries == 0) first_failure = "at its first try (" + format_number(dt_) + " s), " + why;
    ++report.retries;
    if (report.retries > 40)
      // The step it was cut to (0.3^40 of it: 1e-21) says nothing a user can act on; the step
      // it was cut from does.
      throw std::runtime_error("DDA: the time step fell below any use (cut 40 times from " +
                               format_number(first_time_step) + " s without settling, at t = " + format_number(time_) +
                               " s): " + why +
                               (first_failure.find(why) == std::string::npos ? "; " + first_failure : ""));
    // Contact forces that did not settle are given twice the passes once, at the same step,
    // before the step is cut. The augmented Lagrangian converges geometrically, and a shorter
    // static step cannot push out an overlap the step began with (a corner that paired with
    // another edge of a block, deeper than the tolerance from that edge's line): the blocks'
    // inertia M/Δt² then holds them where they stand, and every cut leaves the overlap as it was.
    if (unsettled == Unsettled::contact_forces && lagrangian_limit_ == settings_.max_lagrangian_iterations) {
      lagrangian_limit_ *= 2;
      continue;
    }
    // And then once more with the multipliers mixed (lagrangian_limits.cpp), still uncut.
    if (unsettled == Unsettled::contact_forces && !mixing_multipliers_ && overlaps_held_by_the_blocks_around()) {
      mixing_multipliers_ = true;
      continue;
    }
    // And then with its normal springs stiffened against the blocks' inertia
    // (lagrangian_limits.cpp), still uncut: a shorter step would only slow the passes further.
    if (unsettled == Unsettled::contact_forces && !stiff_normal_springs_ && overlaps_slowed_by_inertia()) {
      stiff_normal_springs_ = true;
      continue;
    }
    dt_ *= settled ? std::max(0.1, 0.9 * allowed_displacement_ / largest) : 0.3;
  }
  report.time = time_;
  report.time_step = dt_;
  for (const auto& [key, r] : records_) {
    if (!is_closed(r.state)) continue;
    ++report.contacts;
    report.max_penetration = std::max(report.max_penetration, r.penetration);
  }
  dt_ = std::min(settings_.time_step, 1.5 * dt_);
  return report;
}

void System::abandon_interrupted_step(double first_time_step, const StepReport& report) {
  undo_pending_bond_breaks();
  dt_ = first_time_step;
  throw StepInterrupted("interrupted within the step from t = " + format_number(time_) + " s, after " +
                        std::to_string(report.lagrangian_iterations) + " solves and " + std::to_string(report.retries) +
                        (report.retries == 1 ? " cut of its time step" : " cuts of its time step"));
}

void System::commit_step(const Eigen::VectorXd& d, double dt) {
  const bool dynamic = settings_.analysis == Analysis::dynamic;
  const auto move = [&](TrackedPoint& tp) {
    const Block& b = blocks_[tp.block];
    if (b.dof >= 0) tp.position = displace_point(tp.position, b.moments.centroid, d.segment<6>(6 * b.dof));
  };
  for (auto* list : {&fixed_points_, &load_points_, &displacement_points_, &measured_})
    for (TrackedPoint& tp : *list) move(tp);
  numerics::for_each_index(many_blocks(), blocks_.size(), [&](std::size_t bi) {
    Block& b = blocks_[bi];
    if (b.dof < 0) return;
    const Vector6 db = d.segment<6>(6 * b.dof);
    const Point c = b.moments.centroid;
    const BlockMotion motion(c, db);
    for (Point& p : b.polygon) p = motion(p);
    b.material_centroid = motion(b.material_centroid);
    b.strain += db.segment<3>(3);
    b.stress += elasticity_[b.material] * db.segment<3>(3);
    b.rotation += db[2];
    // Velocity at the step's end for constant acceleration: v1 = 2 d/Δt − v0.
    b.velocity = dynamic ? Vector6(2.0 / dt * db - b.velocity) : Vector6::Zero();
    b.moments = compute_moments(b.polygon);
  });
  resize_for_overwrite(records_, active_.size());  // active_ is in key order, and so stays records_
  numerics::for_each_index(many_contacts(), active_.size(), [&](std::size_t i) {
    const ActiveContact& c = active_[i];
    ContactRecord r = c.record;  // its penetration the last pass's, from this d (update_state)
    // Parted by more than the tolerance: the next touch closes it at the band, as a new contact.
    if (r.penetration < -penetration_tolerance_) r.released = false;
    if (r.state == ContactState::open) {
      r.multiplier = 0.0;
      r.normal_force = 0.0;
    } else if (r.state == ContactState::sliding) {
      // The shear reference moves to where the vertex now projects on the edge.
      const Polygon& pj = blocks_[c.key.block_j].polygon;
      const Point a = pj[c.key.edge];
      const Point b = pj[(c.key.edge + 1) % pj.size()];
      const Point p = blocks_[c.key.block_i].polygon[c.key.vertex];
      r.reference_ratio = std::clamp(dot(p - a, b - a) / dot(b - a, b - a), 0.0, 1.0);
    }
    records_[i] = {c.key, r};
  });
  preload_new_contacts_ = false;
  start_face_share_ = nullptr;
  time_ += dt;
}

StepReport System::run_steps(int count) {
  StepReport last;
  for (int i = 0; i < count; ++i) last = step();
  return last;
}

StepReport System::run_until(double end_time, const std::function<bool(const StepReport&)>& after_each) {
  StepReport last;
  while (time_ < end_time - 1e-12 * std::max(1.0, end_time)) {
    dt_ = std::min(dt_, end_time - time_);
    last = step();
    if (after_each && after_each(last)) break;
  }
  return last;
}

bool System::ran_at_full_time_step(const StepReport& step) const { return step.time_step >= settings_.time_step; }

bool System::is_at_rest(const StepReport& step) const {
  return ran_at_full_time_step(step) && step.max_displacement <= settings_.static_tolerance * model_size_ &&
         (settings_.unbalanced_force_tolerance <= 0.0 || step.unbalanced_force_ratio <= settings_.unbalanced_force_tolerance);
}

StepReport System::run_to_equilibrium(int max_steps) {
  for (int i = 0; i < max_steps; ++i) {
    const StepReport r = step();
    if (is_at_rest(r)) return r;
  }
  throw std::runtime_error("DDA: no static equilibrium within " + std::to_string(max_steps) +
                           " steps");
}

}  // namespace hydrodda::dda
