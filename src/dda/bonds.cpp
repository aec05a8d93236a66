// Bonds: faces of intact rock between sub-blocks (BlockDefinition::edge_bonds). A bonded face
// is carried by the ordinary vertex–edge contacts at its ends, which start locked and stay
// locked while the bond is intact; the face breaks for good when the traction of its
// sub-blocks' stress exceeds its joint type's tensile strength or shear strength
// (break_overloaded_bonds), or, of a type with a fracture energy, starts to soften in tension
// (softening_bonds.cpp). A
// broken bond is a joint of its type with friction only (System::joint_of). Breaks made in an attempt at a step
// that is then cut are undone with it, so that a bond breaks under the load of the step that
// is kept (docs/dda.md, "Bonds"); where no step can be kept without them, a run breaks those
// of the last try at the state held (break_bonds_of_last_cut_try).
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/system.hpp"

namespace hydrodda::dda {

void System::setup_bonds(const std::vector<BlockDefinition>& blocks, const std::vector<int>& broken_at_start) {
  // Bonds keep their ids; zone face k (−2 − k in edge_bonds) takes the id after them all + k.
  int breakable = 0;
  for (const BlockDefinition& block : blocks)
    for (int id : block.edge_bonds) breakable = std::max(breakable, id + 1);
  std::vector<std::array<BondSide, 2>> sides;
  std::vector<int> seen;  // per bond, the sides found
  edge_bonds_.assign(blocks.size(), {});
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    std::vector<int> bonds = blocks[b].edge_bonds;
    if (bonds.empty()) continue;
    const std::string name = "DDA: block " + std::to_string(b) + ": ";
    if (bonds.size() != blocks[b].polygon.size()) throw std::invalid_argument(name + "edge_bonds needs one entry per edge");
    for (std::size_t e = 0; e < bonds.size(); ++e) {
      if (bonds[e] <= -2) bonds[e] = breakable + (-2 - bonds[e]);
      const int id = bonds[e];
      if (id < 0) continue;
      if (static_cast<std::size_t>(id) >= sides.size()) {
        sides.resize(static_cast<std::size_t>(id) + 1);
        seen.resize(static_cast<std::size_t>(id) + 1, 0);
      }
      int& count = seen[static_cast<std::size_t>(id)];
      if (count == 2) throw std::invalid_argument(name + "bond " + std::to_string(id) + " on more than two edges");
      if (count == 1 && sides[static_cast<std::size_t>(id)][0].block == static_cast<int>(b))
        throw std::invalid_argument(name + "bond " + std::to_string(id) + " on two edges of one block");
      sides[static_cast<std::size_t>(id)][static_cast<std::size_t>(count++)] = {static_cast<int>(b), static_cast<int>(e)};
    }
    edge_bonds_[b] = std::move(bonds);
  }
  for (std::size_t id = 0; id < seen.size(); ++id)
    if (seen[id] != 2)
      throw std::invalid_argument("DDA: bond " + std::to_string(id) + " is on " + std::to_string(seen[id]) +
                                  " edges, not on the two faces it joins");
  bond_sides_ = std::move(sides);
  bond_broken_.assign(bond_sides_.size(), 0);
  breakable_bonds_ = breakable;
  for (int bond : broken_at_start) {
    if (bond < 0 || bond >= breakable_bonds_)
      throw std::invalid_argument("DDA: broken_bonds names bond " + std::to_string(bond) + ", and there are " +
                                  std::to_string(breakable_bonds_) + " that may break");
    bond_broken_[static_cast<std::size_t>(bond)] = 1;
  }
  broken_at_start_ = broken_at_start;
  // l̄: half the mean face length, the tributary length of a face's end on average.
  double total = 0.0;
  for (const std::array<BondSide, 2>& s : bond_sides_) {
    const Polygon& p = blocks[static_cast<std::size_t>(s[0].block)].polygon;
    total += geometry::distance(p[static_cast<std::size_t>(s[0].edge)], p[(static_cast<std::size_t>(s[0].edge) + 1) % p.size()]);
  }
  if (!bond_sides_.empty()) bond_reference_length_ = 0.5 * total / static_cast<double>(bond_sides_.size());
}

// Pseudocode:
//   for each intact bond, n its face's unit normal, t along it:
//     σ = the mean stress of its two sub-blocks at the end of the step under d (a fixed
//         block, which carries none, left out)
//     σn = n·σ·n (tension positive), τ = t·σ·n
//     σn > T                     → broken in tension (softening, with a fracture energy)
//     |τ| > c + max(−σn, 0) tan φ → broken in shear
// The face's traction is read from the sub-blocks' stresses, not from its contacts' forces:
// the uniform-strain blocks leave the forces of single contacts, and their sums over a face,
// scattered about the traction times the length (the six unknowns of a block cannot give each
// contact its share; a bar of Voronoi sub-blocks in uniform tension had faces whose two
// contacts carried 20% more than σn L), while the stresses are the field's own, uniform where
// it is (docs/dda.md, "Bonds").
bool System::break_overloaded_bonds(const Eigen::VectorXd& d) {
  const auto stress_at_end = [&](int block) -> std::optional<Vector3> {
    const Block& b = blocks_[static_cast<std::size_t>(block)];
    if (b.dof < 0) return std::nullopt;
    return Vector3(b.stress + elasticity_[static_cast<std::size_t>(b.material)] * d.segment<3>(6 * b.dof + 3));
  };
  bool any = false;
  for (std::size_t bond = 0; bond < static_cast<std::size_t>(breakable_bonds_); ++bond) {
    if (bond_broken_[bond] != 0) continue;
    const std::optional<Vector3> a = stress_at_end(bond_sides_[bond][0].block);
    const std::optional<Vector3> b = stress_at_end(bond_sides_[bond][1].block);
    if (!a && !b) continue;
    const Vector3 sigma = a && b ? Vector3(0.5 * (*a + *b)) : (a ? *a : *b);
    const std::array<Point, 2> face = bond_face(static_cast<int>(bond));
    const Point t = (face[1] - face[0]) / geometry::distance(face[0], face[1]);
    const Point n{t.y, -t.x};  // out of the first sub-block (counter-clockwise)
    const Point traction{sigma[0] * n.x + sigma[2] * n.y, sigma[2] * n.x + sigma[1] * n.y};
    const double normal = dot(traction, n);
    const double shear = dot(traction, t);
    const JointStrength& strength = joints_[static_cast<std::size_t>(bond_joint_type(static_cast<int>(bond)))];
    BondFailure mode = BondFailure::none;
    if (normal > strength.tensile_strength)
      mode = BondFailure::tension;
    else if (std::abs(shear) > strength.cohesion + std::max(-normal, 0.0) * strength.tan_friction)
      mode = BondFailure::shear;
    if (mode == BondFailure::none) continue;
    any = true;
    if (mode == BondFailure::tension && strength.fracture_energy > 0.0) {
      start_softening(static_cast<int>(bond));  // softening_bonds.cpp
      continue;
    }
    bond_broken_[bond] = 1;
    pending_breaks_.emplace_back(static_cast<int>(bond), mode);
  }
  return any;
}

void System::undo_pending_bond_breaks() {
  for (const auto& [bond, mode] : pending_breaks_) bond_broken_[static_cast<std::size_t>(bond)] = 0;
  pending_breaks_.clear();
  if (!softening_.empty()) undo_pending_softening();
}

void System::record_pending_bond_breaks() {
  for (const auto& [bond, mode] : pending_breaks_) {
    const std::array<Point, 2> face = bond_face(bond);
    bond_breaks_.push_back({bond, time_, mode, face[0], face[1]});
  }
  pending_breaks_.clear();
  if (!softening_.empty()) commit_softening();
}

int System::break_bonds_of_last_cut_try() {
  for (const auto& [bond, mode] : last_cut_try_breaks_) {
    char& state = bond_broken_[static_cast<std::size_t>(bond)];
    if (state == 1) continue;
    state = 1;
    pending_breaks_.emplace_back(bond, mode);
  }
  last_cut_try_breaks_.clear();
  const int count = static_cast<int>(pending_breaks_.size());
  record_pending_bond_breaks();
  return count;
}

std::array<Point, 2> System::bond_face(int bond) const {
  const BondSide& side = bond_sides_.at(static_cast<std::size_t>(bond))[0];
  const Polygon& p = blocks_[static_cast<std::size_t>(side.block)].polygon;
  return {p[static_cast<std::size_t>(side.edge)], p[(static_cast<std::size_t>(side.edge) + 1) % p.size()]};
}

// A corner of intact rock: of the two faces at vertex v of `block`, each an intact bond or a
// face of no bond (the edge of the tessellated rock: a joint, a trace, the domain's boundary),
// and one at least an intact bond. A broken or softening face makes it a crack's corner.
bool System::is_corner_of_intact_rock(int block, int vertex) const {
  const std::vector<int>& bonds = edge_bonds_[static_cast<std::size_t>(block)];
  if (bonds.empty()) return false;
  const std::size_t n = bonds.size();
  const std::size_t v = static_cast<std::size_t>(vertex);
  bool bonded = false;
  for (const int bond : {bonds[v], bonds[(v + n - 1) % n]}) {
    if (bond < 0) continue;
    if (bond_broken_[static_cast<std::size_t>(bond)] != 0) return false;
    bonded = true;
  }
  return bonded;
}

// Where several sub-blocks of intact rock meet at a node, each one's corner there lies on the
// ends of the faces of the others. Its own two faces are bonded to its neighbours, whose
// corners stand between it and the rest: a third sub-block's corner can reach it only through
// them. The constant-strain sub-blocks' corners at a node part by their faces' penalty
// compliance (1e-7 m), so a corner sits just inside or just past another's, tip to tip: the
// edge it is taken against flips with that (the entrance edge, or none past the corner), and
// each flip moves the sub-block by as much, from step to step without end (the seal through
// intact rock, 1 m triangles at 1,100 m over hydrostatic: a 2e-7 m two-step cycle, at rest never).
// So where two corners at a node are both of intact rock (each one's faces intact bonds, or
// one of them on the rock's edge: a node on a joint that bounds the tessellated rock, whose
// sub-blocks fan out below the joint, bonded to each other), the one has no contact with the
// other's bonded faces' ends; a broken face at either gives the contact back (a crack through
// the node, its corners joints' again). On the rock's edge: a node welded just below a bedding
// joint whose corners' contacts never settled (docs/studies/2026-11-30-bonds-at-scale.md).
// At a node where a crack ends, a corner keeps its contacts with the broken faces and with its
// two neighbours' faces, but not with the intact faces past them that it reaches about the
// node through intact faces (bonded_about_node): its neighbours stand between. It
// may have slid along such a face's end by more than the tie, so the end is looked for within
// the contact distance (the resolved seal's first breaks: a corner 8e-7 m into the end of an
// intact face two sub-blocks away across the node, contact forces that never settled). Along a
// crack through the node, the corners across it keep theirs; at a crack's tip, those beside it
// keep their neighbours' faces, which may break next (without them a running crack of softening
// bonds failed a step: docs/studies/2026-11-30-intact-seal-tip.md).
// A corner beside a crack (one face at the node broken or softening, the other intact) has no
// contact either with a broken face's end of a sub-block it reaches about the node through
// intact faces (the face's own two corners excepted): it moves with the crack's opening, the
// face's end does not, and the intact rock between holds the two together, so their corners'
// overlap is one that no force on the contact removes (the resolved seal's step that never
// settled, and did not at the full penalty either). A corner of intact rock keeps such
// contacts: they settle, and without them the verification cases' running cracks took other
// paths (the same study).
void System::drop_corner_contacts_within_intact_rock(ContactCandidates& candidates) const {
  if (bond_sides_.empty()) return;
  const double tie = 1e-3 * contact_distance_;  // contact_detection.cpp's corner tie
  // Whether `corner` of the candidate's edge block is reached about the node from its corner
  // through intact faces.
  const auto reached_about_node = [&](const ContactCandidate& c, int corner) {
    const std::vector<NodeCorner> about = bonded_about_node(c.key.block_i, c.key.vertex);
    return std::find(about.begin(), about.end(), NodeCorner{c.key.block_j, corner}) != about.end();
  };
  // Whether the intact face `bond` of the candidate is past the corner's neighbours at its node
  // (neither of its two sub-blocks one of them) and reached through them to `corner` of it.
  const auto shielded_by_neighbours = [&](const ContactCandidate& c, int bond, int corner) {
    const std::array<BondSide, 2>& sides = bond_sides_[static_cast<std::size_t>(bond)];
    const int other = sides[0].block == c.key.block_j ? sides[1].block : sides[0].block;
    const std::vector<int>& own = edge_bonds_[static_cast<std::size_t>(c.key.block_i)];
    const std::size_t n = own.size(), v = static_cast<std::size_t>(c.key.vertex);
    // A block built without bonds (edge_bonds empty) has faces of no bond at the corner.
    if (n > 0)
      for (const int face : {own[v], own[(v + n - 1) % n]}) {
        if (face < 0) continue;
        for (const BondSide& side : bond_sides_[static_cast<std::size_t>(face)])
          if (side.block != c.key.block_i && (side.block == c.key.block_j || side.block == other)) return false;
      }
    return reached_about_node(c, corner);
  };
  const auto tip_to_tip_within_intact_rock = [&](const ContactCandidate& c) {
    const int bond = bond_of(c.key);
    if (bond < 0 || bond_across(c.key) >= 0) return false;  // no bond, or the face's own
    const auto [corner, to_corner] = edge_end_nearest(c.key);
    if (to_corner <= tie && is_corner_of_intact_rock(c.key.block_i, c.key.vertex) &&
        is_corner_of_intact_rock(c.key.block_j, corner))
      return true;
    if (to_corner > contact_distance_) return false;
    if (bond_broken_[static_cast<std::size_t>(bond)] == 0) return shielded_by_neighbours(c, bond, corner);
    return !is_corner_of_intact_rock(c.key.block_i, c.key.vertex) && reached_about_node(c, corner);
  };
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(), tip_to_tip_within_intact_rock), candidates.end());
}

System::EdgeEnd System::edge_end_nearest(const ContactKey& key) const {
  const Polygon& edge_block = blocks_[static_cast<std::size_t>(key.block_j)].polygon;
  const Point p = blocks_[static_cast<std::size_t>(key.block_i)].polygon[static_cast<std::size_t>(key.vertex)];
  const auto start = static_cast<std::size_t>(key.edge);
  const std::size_t end = (start + 1) % edge_block.size();
  const double to_start = geometry::distance(p, edge_block[start]);
  const double to_end = geometry::distance(p, edge_block[end]);
  return to_start <= to_end ? EdgeEnd{static_cast<int>(start), to_start} : EdgeEnd{static_cast<int>(end), to_end};
}

// The sub-blocks about the node at corner `vertex` of `block` that it reaches through intact
// bonded faces without crossing a broken one or a face of no bond, each with its corner there
// (the start left out). At a crack's tip they stand between the corners beside the crack and
// the intact faces' ends across the node; along a crack through the node, those of the far side
// are not among them.
//
// Pseudocode (a face's two sides run opposite ways: X[k] ↔ Y[e + 1], X[k + 1] ↔ Y[e]):
//   for each way about the node:
//     (B, w) = (block, vertex)
//     repeat: the face of B at w that way (edge w forward, edge w − 1 back) an intact bond
//             to (C, e), else stop; (B, w) = (C, e + 1) forward, (C, e) back; stop back at the start
std::vector<System::NodeCorner> System::bonded_about_node(int block, int vertex) const {
  std::vector<NodeCorner> reached;
  for (const bool forward : {true, false}) {
    NodeCorner at{block, vertex};
    for (std::size_t guard = 0; guard < 64; ++guard) {  // a node of a tessellation has a handful
      const std::vector<int>& bonds = edge_bonds_[static_cast<std::size_t>(at.block)];
      if (bonds.empty()) break;
      const std::size_t n = bonds.size();
      const auto w = static_cast<std::size_t>(at.vertex);
      const int bond = bonds[forward ? w : (w + n - 1) % n];
      if (bond < 0 || bond_broken_[static_cast<std::size_t>(bond)] != 0) break;
      const std::array<BondSide, 2>& sides = bond_sides_[static_cast<std::size_t>(bond)];
      const BondSide& next = sides[0].block == at.block ? sides[1] : sides[0];
      if (next.block == block) return reached;  // round the node: every face at it intact
      const std::size_t n_next = blocks_[static_cast<std::size_t>(next.block)].polygon.size();
      at = {next.block, static_cast<int>(forward ? (static_cast<std::size_t>(next.edge) + 1) % n_next
                                                 : static_cast<std::size_t>(next.edge))};
      reached.push_back(at);
    }
  }
  return reached;
}

// An intact bonded face is carried by one vertex–edge contact at each end (Shi 1988, §4.3); where
// its two corners there coincide, find_pair_contacts keeps one. Where they have parted along the
// face by more than the corner tie, the corner past the other's edge end was kept too while
// within the tie of the line of that block's next edge: a second locked contact, which pulled
// the corners back within the tie, where they were one corner again (a crack's opening tip: a
// two-step cycle that never came to rest). So that corner has no contact with the face where
// the other corner lies within its own face (a choice that changes only as the ends slide past
// each other, not on the tie); a broken face keeps both.
//
// Pseudocode:
//   for each candidate c = (corner v of X, edge e of Y) across an intact bond:
//     k = X's edge of the bond; skip unless v is an end of it
//     u = Y's corner at that end (the faces run opposite ways: X[k] ↔ Y[e + 1], X[k + 1] ↔ Y[e])
//     drop c if v projects past the ends of Y's edge e, the candidates hold (u, X's edge k),
//     and u projects within X's edge k
void System::drop_second_contacts_at_intact_face_ends(ContactCandidates& candidates) const {
  if (bond_sides_.empty()) return;
  const auto point = [&](int block, std::size_t vertex) {
    const Polygon& p = blocks_[static_cast<std::size_t>(block)].polygon;
    return p[vertex % p.size()];
  };
  // Whether `p` projects within edge `edge` of `block` (its ends included).
  const auto within_edge = [&](Point p, int block, int edge) {
    const Point a = point(block, static_cast<std::size_t>(edge));
    const Point b = point(block, static_cast<std::size_t>(edge) + 1);
    const double t = dot(p - a, b - a) / dot(b - a, b - a);
    return t >= 0.0 && t <= 1.0;
  };
  const auto has_candidate = [&](const ContactKey& key) {  // the candidates are in key order
    const auto at = std::lower_bound(candidates.begin(), candidates.end(), key,
                                     [](const ContactCandidate& c, const ContactKey& k) { return c.key < k; });
    return at != candidates.end() && at->key == key;
  };
  const auto second_at_the_end = [&](const ContactCandidate& c) {
    const int bond = bond_across(c.key);
    if (bond < 0 || bond_broken_[static_cast<std::size_t>(bond)] != 0) return false;
    const std::array<BondSide, 2>& sides = bond_sides_[static_cast<std::size_t>(bond)];
    const int own_edge = sides[0].block == c.key.block_i ? sides[0].edge : sides[1].edge;
    const std::size_t n_own = blocks_[static_cast<std::size_t>(c.key.block_i)].polygon.size();
    const std::size_t n_other = blocks_[static_cast<std::size_t>(c.key.block_j)].polygon.size();
    const auto k = static_cast<std::size_t>(own_edge);
    const auto v = static_cast<std::size_t>(c.key.vertex);
    if (v != k && v != (k + 1) % n_own) return false;  // not a corner of the bonded face
    const auto e = static_cast<std::size_t>(c.key.edge);
    const int other_corner = static_cast<int>(v == k ? (e + 1) % n_other : e);
    const ContactKey other{c.key.block_j, other_corner, c.key.block_i, own_edge};
    return !within_edge(point(c.key.block_i, v), c.key.block_j, c.key.edge) && has_candidate(other) &&
           within_edge(point(c.key.block_j, static_cast<std::size_t>(other_corner)), c.key.block_i, own_edge);
  };
  std::vector<char> drop(candidates.size(), 0);
  for (std::size_t i = 0; i < candidates.size(); ++i) drop[i] = second_at_the_end(candidates[i]) ? 1 : 0;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (drop[i] == 0) candidates[kept++] = candidates[i];
  candidates.resize(kept);
}

// A corner of another block standing on the face of intact rock at a node, where the face of one
// sub-block meets that of the next across their bond, touches the first sub-block's edge while
// it stands a hair over that edge and is past the edge's end (the entrance-edge rule,
// contact_detection.cpp) once it stands a hair beyond the node: contact, then none, then
// contact, as each state moved it back across (a bed's corner where a steep joint meets the
// notched seal through intact rock, from 953 m over hydrostatic: 1.5e-7 m a step, never at rest;
// docs/studies/2026-11-30-notched-seal.md). The node is no corner of the rock: beyond it lies
// the next sub-block, bonded to the first. So a candidate a hair past a sub-block's corner that
// is a corner of intact rock (is_corner_of_intact_rock) keeps its contact while it was closed
// at the last step: a hysteresis in the contact's existence, within the corner tie of the node
// and the penetration tolerance behind the edge's line (ContactCandidate::kept_if_closed).
void System::drop_corner_candidates_not_kept(ContactCandidates& candidates) const {
  if (bond_sides_.empty()) return;
  const auto not_kept = [&](const ContactCandidate& c) {
    if (!c.kept_if_closed) return false;
    if (!is_corner_of_intact_rock(c.key.block_j, edge_end_nearest(c.key).corner)) return true;
    const auto record = std::lower_bound(records_.begin(), records_.end(), c.key,
                                         [](const auto& r, const ContactKey& key) { return r.first < key; });
    return record == records_.end() || record->first != c.key || record->second.state == ContactState::open;
  };
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(), not_kept), candidates.end());
}

void System::apply_bond_rules(ContactCandidates& candidates) const {
  drop_corner_contacts_within_intact_rock(candidates);
  drop_second_contacts_at_intact_face_ends(candidates);
  drop_corner_candidates_not_kept(candidates);
}

// A bond that breaks in a pass of a try frees its faces' corners from the bond rules, but the
// try goes on with the contacts found at its start, and a corner those rules left without a
// contact may run into a neighbour unchecked: where three cracks met at a node of the strip seal
// (tutorial_intact_seal.md, 1,200 m on the path from 600 m), a corner went 27 µm into the
// sub-block across the node in the step that broke two of the faces there, and no later step
// could push it out. So a try that settles having broken bonds applies the rules again to its
// search's candidates: a contact they now keep that the try did not have, whose vertex the try's
// motion d took inside the edge's block deeper than the penetration tolerance, sends the step
// back to its start with those bonds broken (System::step). Only such a one: freed contacts that
// stay apart change nothing, and a disc's cascade of breaks, each sending its step back, ran
// into steps whose contact forces never settled.
bool System::breaks_let_corners_in(const Eigen::VectorXd& d) const {
  if (pending_breaks_.empty()) return false;
  ContactCandidates now = detection_.before_bond_rules;
  apply_bond_rules(now);
  const auto moved = [&](int block) {
    const Block& b = blocks_[static_cast<std::size_t>(block)];
    Polygon polygon = b.polygon;
    if (b.dof < 0) return polygon;
    const BlockMotion motion(b.moments.centroid, d.segment<6>(6 * b.dof));
    for (Point& q : polygon) q = motion(q);
    return polygon;
  };
  auto had = active_.begin();  // both in key order
  for (const ContactCandidate& c : now) {
    while (had != active_.end() && had->key < c.key) ++had;
    if (had != active_.end() && had->key == c.key) continue;
    const Polygon edge_block = moved(c.key.block_j);
    const Point p = moved(c.key.block_i)[static_cast<std::size_t>(c.key.vertex)];
    const Point a = edge_block[static_cast<std::size_t>(c.key.edge)];
    const Point b = edge_block[(static_cast<std::size_t>(c.key.edge) + 1) % edge_block.size()];
    const double depth = geometry::orient(a, b, p) / geometry::distance(a, b);
    if (depth > penetration_tolerance_ && geometry::contains(edge_block, p)) return true;
  }
  return false;
}

int System::bond_joint_type(int bond) const {
  const BondSide& side = bond_sides_.at(static_cast<std::size_t>(bond))[0];
  const std::vector<int>& types = edge_joints_[static_cast<std::size_t>(side.block)];
  return types.empty() ? 0 : types[static_cast<std::size_t>(side.edge)];
}

}  // namespace hydrodda::dda
