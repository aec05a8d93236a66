#pragma once
// The DDA system: blocks in frictional contact advanced one time step at a time.
// A step reads as its stages: update bounds → find pairs → detect contacts → assemble →
// open–close (augmented Lagrangian inside) → update geometry → report.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "dda/block_kernels.hpp"
#include "dda/contact_detection.hpp"
#include "dda/contact_search.hpp"
#include "dda/free_drift.hpp"
#include "dda/initial_stress.hpp"
#include "dda/definitions.hpp"
#include "dda/linear_solver.hpp"
#include "numerics/anderson.hpp"

namespace hydrodda::dda {

enum class ContactState { open, sliding, locked };

// A contact as the user sees it.
struct ContactInfo {
  ContactKey key;
  ContactState state = ContactState::open;
  double penetration = 0.0;   // > 0 overlap, < 0 gap (m)
  double normal_force = 0.0;  // compression positive (N per metre)
};

struct StepReport {
  double time = 0.0;          // at the end of the step
  double time_step = 0.0;
  int open_close_iterations = 0;
  int lagrangian_iterations = 0;
  int retries = 0;            // step cuts before this step settled
  int most_breaks_in_a_cut_try = 0;  // the most bonds one try broke before it was cut (mended then)
  int tries_with_bonds_broken = 0;   // tries again from the start with bonds broken (breaks_let_corners_in)
  int contacts = 0;           // closed contacts at the end of the step
  double max_displacement = 0.0;  // largest vertex displacement in the step
  double max_penetration = 0.0;   // deepest closed contact at the end of the step
  // The step's unbalanced force (System::measure_unbalanced_force): the largest over the
  // blocks of the step's inertial force 2 m |d| / Δt² (d its centroid's displacement) over
  // the magnitudes of the forces on the block; the block it was largest on (−1: none).
  double unbalanced_force_ratio = 0.0;
  int unbalanced_block = -1;
  // Of the blocks the step moved freely (by more than the at-rest test allows, held by
  // nothing at rest) and that will land at this step's rates, on what is at rest or behind a
  // block that lands first: the most steps one takes to land, and that block (0 and −1: no
  // such block); a block the step moved freely that meets nothing (−1: none). Each block's:
  // System::free_drift().
  double free_drift_steps = 0.0;
  int free_drift_block = -1;
  int block_meeting_nothing = -1;
};

// How a bond (a face of intact rock between two sub-blocks) failed.
enum class BondFailure : char { none, tension, shear };

// A bond that broke: in the step that ended at `time`, by `mode`, the face then from `from` to
// `to` (the first block's edge, as it was at the step's end).
struct BondBreak {
  int bond = 0;
  double time = 0.0;
  BondFailure mode = BondFailure::none;
  Point from, to;
};

// A bond softening over its fracture energy (dda/softening_bonds.cpp): the largest opening
// each end of its face (the first block's edge's start and end) has reached at a step's end.
struct SofteningBond {
  int bond = 0;
  std::array<double, 2> peak_opening{0.0, 0.0};  // m
};

// Persistent contact state (Shi's contact transfer): carried between steps by key.
struct ContactRecord {
  ContactState state = ContactState::open;
  double reference_ratio = 0.0;  // shear reference point on the edge
  double multiplier = 0.0;       // augmented-Lagrangian normal force λ
  int slide_sign = 0;            // direction of sliding along the edge
  double normal_force = 0.0;
  double penetration = 0.0;
  // Opened by the tension cutoff and not parted since by more than the penetration tolerance:
  // it closes again only by penetrating past that tolerance (System::update_state).
  bool released = false;
};

// The evolving state of a System as plain data: what a checkpoint holds to continue a run
// exactly. Everything else in a System follows from its ModelDefinition.
struct SystemState {
  struct BlockState {
    Polygon polygon;
    std::array<double, 6> velocity{};
    std::array<double, 3> stress{};
    std::array<double, 3> strain{};
    double rotation = 0.0;
    Point material_centroid;
  };
  std::vector<BlockState> blocks;
  double time = 0.0;
  double time_step = 0.0;  // the step the next step starts from (it may have been cut)
  std::vector<std::pair<ContactKey, ContactRecord>> contacts;  // in key order
  // Current positions of the tracked points, in definition order.
  std::vector<Point> fixed_points, load_points, displacement_points, measured_points;
  std::vector<std::vector<Point>> vertex_forces;
  std::vector<double> roller_reliefs;  // in definition order (System::relieve_start_loads)
  std::vector<BondBreak> bond_breaks;  // the bonds broken so far, in the order they broke
  std::vector<SofteningBond> softening_bonds;  // those softening, not yet broken
};

// Thrown by System::step when its interrupt check asks it to stop: the step is abandoned and
// the system is as the last finished step left it.
struct StepInterrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class System {
 public:
  explicit System(ModelDefinition definition,
                  std::unique_ptr<LinearSolver> solver = make_block_factor_solver());

  // One time step (cut and retried as needed).
  StepReport step();
  // Asked before each try at a step and before each of its open–close passes (a pass is
  // bounded: at most twice max_lagrangian_iterations solves, each at most its solver's
  // iterations and two factorisations): true abandons the step, leaving the system as the last
  // finished step left it, and throws StepInterrupted. A step on a large model can take many
  // passes (docs/dda.md, "How long a step may take"); this is how a run stops within one.
  // Unset: never asked.
  void set_interrupt_check(std::function<bool()> check) { interrupt_check_ = std::move(check); }
  // `count` steps; the last report.
  StepReport run_steps(int count);
  // Steps until `end_time`, the last step shortened to land on it. `after_each`, when given, is
  // handed each step's report; its true ends the run there, short of end_time.
  StepReport run_until(double end_time, const std::function<bool(const StepReport&)>& after_each = {});
  // Lets go of the contact list each step rebuilds (some 300 bytes a candidate: about 110 MB
  // at 10^4 blocks), kept from step to step to spare its page faults. A coupled run calls it
  // between passes, while the flow model factors and the fields are written; the next step
  // makes it again. Nothing a step or a query reads between steps is lost.
  void release_step_buffers();
  // Whether a step left the blocks at rest: it ran at the full time step (one cut short moves
  // little for being short), moved no vertex by more than settings.static_tolerance × model
  // size, and left no block an unbalanced force above settings.unbalanced_force_tolerance of
  // the forces on it (a body that nothing holds moves by F Δt²/2M a static step, which the
  // displacement test alone passes when Δt is short).
  bool is_at_rest(const StepReport& step) const;
  // The largest vertex displacement a step may make and leave the blocks at rest (m).
  double at_rest_displacement() const { return settings_.static_tolerance * model_size_; }
  // Each block's displacement in the last step and the steps it takes to land at its rates.
  const FreeDrift& free_drift() const { return free_drift_; }
  // Moves `blocks` rigidly by `shift` between steps (block_translation.cpp): their vertices,
  // centroids and the points tracked on them; stresses, strains and contact records stay. For
  // a group that meets nothing, moved by the coupled loop to where its net load vanishes.
  // Throws std::invalid_argument for a block that does not exist or is fixed.
  void translate_blocks(std::span<const int> blocks, Point shift);
  // Whether a step ran at settings.time_step, not cut short (by an open–close iteration that
  // did not settle, or a displacement past the allowed one).
  bool ran_at_full_time_step(const StepReport& step) const;
  double full_time_step() const { return settings_.time_step; }
  // Static analysis: steps until one leaves the blocks at rest, at most max_steps; throws if
  // it never gets there.
  StepReport run_to_equilibrium(int max_steps);

  // External forces per block per vertex (N per metre), e.g. fluid forces; replaces the last.
  // forces[b] must be empty or hold one force per vertex of block b.
  void set_vertex_forces(std::vector<std::vector<Point>> forces);
  // Before the first step of a run that starts in its in-situ stress: the blocks carry the
  // initial stress, but a fluid that pushes on their faces takes part of what the contacts and
  // rollers carried across them. Each roller's preload, and each contact's found touching in the
  // first step, is made less by `share`'s push on the faces it carries (the faces of its vertex
  // along the boundary; those along the contact's edge). For Biot's α and a pore pressure p,
  // with faces pushed by (1 − α) p: blocks in σ + α p I, contacts and rollers in (σ + p I) n.
  // Does nothing at a time after 0 or without an initial stress.
  void relieve_start_loads(FaceShare share);
  // Replaces the edge tractions from the next step on (a loading path changed between steps);
  // throws std::invalid_argument for a block or edge that does not exist.
  void set_tractions(std::vector<EdgeTraction> tractions);
  // The time the loads given as time tables (tractions, point loads) are read at: unset, the
  // end of each step (time() + Δt); set, that time for every step until changed (a coupled
  // run's load step, docs/scenario.md "Loads over time"). Not part of the state: whoever sets
  // it sets it again after an import.
  void hold_load_time(std::optional<double> load_time) { held_load_time_ = load_time; }
  std::optional<double> held_load_time() const { return held_load_time_; }

  // The evolving state, and its restoration into a System built from the same definition
  // (import throws std::invalid_argument when the counts do not fit). Importing also restarts
  // the linear solver, so that the steps after it do not depend on factors reused from before.
  SystemState export_state() const;
  void import_state(const SystemState& state);

  int block_count() const { return static_cast<int>(blocks_.size()); }
  double time() const { return time_; }
  const Polygon& polygon(int block) const { return blocks_[block].polygon; }
  Point centroid(int block) const { return blocks_[block].moments.centroid; }
  double area(int block) const { return blocks_[block].moments.area; }
  int material(int block) const { return blocks_[block].material; }  // index into the definition's materials
  int material_count() const { return static_cast<int>(materials_.size()); }
  // Displacement of the centroid since the start (the material centroid, followed).
  Point displacement(int block) const;
  double rotation(int block) const { return blocks_[block].rotation; }
  // σxx, σyy, τxy (Pa), uniform in the block.
  std::array<double, 3> stress(int block) const;
  // εx, εy, γxy accumulated since the start.
  std::array<double, 3> strain(int block) const;
  std::vector<ContactInfo> contacts() const;
  // Per block, the magnitudes of the forces on it (N/m): its weight, each applied load's
  // resultant (vertex forces, tractions, point loads) and its closed contacts' normal forces
  // at the last step's end: what an unbalanced force is measured against.
  std::vector<double> force_magnitudes() const;
  std::vector<Point> measured_positions() const;
  // Each prescribed displacement's point: where the ramp wants it now, and where it is, both
  // as displacements from its start.
  struct PrescribedProgress {
    Point point;    // where it started
    Point target;   // min(1, t / ramp_time) · value
    Point reached;  // its displacement now
    // How far its block's own elasticity moves it under the block's stress: |σ|max √A / E.
    // The springs that impose it (10 × the penalty, 500 E per metre) yield some 500 times less
    // than the block under the same load.
    double elastic_scale = 0.0;
    // The force its springs exert on the block (N/m): the support's reaction on the rock.
    Point reaction;
    int entry = 0;  // PrescribedDisplacement::entry
  };
  std::vector<PrescribedProgress> prescribed_progress() const;
  double penalty() const { return penalty_; }
  double penetration_tolerance() const { return penetration_tolerance_; }
  double allowed_step_displacement() const { return allowed_displacement_; }
  SolverCounts solver_counts() const { return solver_->counts(); }

  // Bonds (BlockDefinition::edge_bonds; dda/bonds.cpp): how many, which broke and when, and a
  // bond's face as it is now (the first block's edge that carries it).
  int bond_count() const { return breakable_bonds_; }  // zone faces (BlockDefinition::edge_bonds) not among them
  bool is_bond_broken(int bond) const { return bond_broken_[static_cast<std::size_t>(bond)] == 1; }
  // A bond of a type with a fracture energy, past its strength and not yet broken: its faces
  // held by a cohesive traction (dda/softening_bonds.cpp); its contacts a joint's.
  bool is_bond_softening(int bond) const { return bond_broken_[static_cast<std::size_t>(bond)] == 2; }
  // The opening of a bond's face at its two ends (the first block's edge's start and end), m:
  // the second block's matching vertex off the first's edge, along its outward normal.
  std::array<double, 2> bond_opening(int bond) const;
  // The cohesive traction (Pa) a softening bond's face carries at its ends at `opening`.
  std::array<double, 2> bond_cohesive_traction(int bond, std::array<double, 2> opening) const;
  const std::vector<BondBreak>& bond_breaks() const { return bond_breaks_; }
  // Breaks, at the state now held, the bonds that the last cut try to break any broke, and
  // returns how many of them were still intact: a static run's way past a load it can no
  // longer raise (run/load_stall.hpp).
  int break_bonds_of_last_cut_try();
  std::array<Point, 2> bond_face(int bond) const;
  int bond_joint_type(int bond) const;  // 0: `joint`, i: joint_types[i − 1]
  // The bond whose face a contact's vertex touches (its edge a bonded face), or −1.
  int bond_of_contact(const ContactKey& key) const { return bond_of(key); }
  // The bond on edge `edge` of block `block`, or −1.
  int bond_of_edge(int block, int edge) const {
    const std::vector<int>& bonds = edge_bonds_[static_cast<std::size_t>(block)];
    return bonds.empty() ? -1 : bonds[static_cast<std::size_t>(edge)];
  }

 private:
  struct Block {
    Polygon polygon;
    Moments moments;
    int material = 0;
    int dof = -1;  // first unknown ÷ 6, or −1 for a fixed block
    Vector6 velocity = Vector6::Zero();
    Vector3 stress = Vector3::Zero();
    Vector3 strain = Vector3::Zero();
    double rotation = 0.0;
    Point material_centroid;  // the initial centroid, followed as a material point
    Point initial_centroid;
  };
  struct TrackedPoint {
    int block = 0;
    Point position;
    Point initial;
  };
  // Linearised contact (Shi 1988 §4): penetration d = d0 + en·D, shear s = s0 + es·D.
  // What every candidate's pass reads comes first (208 of its 368 bytes): most candidates of a
  // large model stay open, and a step walks all of them several times.
  struct ActiveContact {
    ContactKey key;
    ContactRecord record;
    double penetration0 = 0.0;
    int dof_i = -1, dof_j = -1;
    // Changed state in one of this step's open–close passes.
    bool changed_in_step = false;
    // Its penetration as the last pass measured it (the try's start before the first).
    double pass_penetration = 0.0;
    Vector6 en_i = Vector6::Zero(), en_j = Vector6::Zero();
    // Made when the contact is closed at the step's start or closes in a pass
    // (linearise_closed_contact), and read only while it is closed: an open contact's are
    // left as they were, not written for nothing.
    double shear0 = 0.0;
    double length = 0.0;  // the face length it carries (tributary_length)
    double stiffness = 0.0;  // its springs' penalty (contact_stiffness)
    // Its normal spring's penalty in the try under way (normal_spring), set as each pass
    // factors: p, or stiffer in a step short enough that the blocks' inertia rivals p.
    double normal_stiffness = 0.0;
    Vector6 es_i = Vector6::Zero(), es_j = Vector6::Zero();
    // Its last change of state, written only as it changes and read only when a step's states
    // do not settle (unsettled_states.cpp): the pass (−1: none in this try), the state and the
    // penetration before it, and whether it had changed already in the step.
    int changed_pass = -1;
    bool changed_back = false;
    ContactState state_before = ContactState::open;
    double penetration_before = 0.0;
  };
  // Whether a loop is long enough to pay for a second thread, which can take some tens of
  // microseconds to wake: one over the blocks (a few hundred nanoseconds each), one that
  // linearises the contacts (about a hundred nanoseconds each), or one of a pass's light
  // loops over them (ten or twenty nanoseconds each).
  bool many_blocks() const { return blocks_.size() >= 500; }
  bool many_contacts_to_linearise() const { return active_.size() >= 2000; }
  bool many_contacts() const { return active_.size() >= 5000; }
  bool many_closed_contacts() const { return closed_.size() >= 5000; }  // loops over closed_
  void check_tractions(std::span<const EdgeTraction> tractions) const;
  void detect_contacts();
  // bonds.cpp: drops a corner's contacts with the ends of other sub-blocks' bonded faces where
  // both corners are of intact rock, inside it or on its edge (tip to tip at a node of the
  // tessellation).
  bool is_corner_of_intact_rock(int block, int vertex) const;
  // A sub-block's corner at a node of the tessellation.
  struct NodeCorner {
    int block = -1;
    int vertex = -1;
    bool operator==(const NodeCorner&) const = default;
  };
  // The end of a contact's edge nearer its vertex: that corner of the edge's block, and how far.
  struct EdgeEnd {
    int corner = -1;
    double distance = 0.0;
  };
  EdgeEnd edge_end_nearest(const ContactKey& key) const;
  // bonds.cpp: the corners about a corner's node that it reaches through intact bonded faces.
  std::vector<NodeCorner> bonded_about_node(int block, int vertex) const;
  void drop_corner_contacts_within_intact_rock(ContactCandidates& candidates) const;
  // bonds.cpp: drops, at an end of an intact bonded face whose two corners have parted along it,
  // the contact of the corner past the other's edge where the other's lies within its own.
  void drop_second_contacts_at_intact_face_ends(ContactCandidates& candidates) const;
  // bonds.cpp: of the candidates a hair past a corner (ContactCandidate::kept_if_closed), keeps
  // those at a node of intact rock whose contact was closed at the last step.
  void drop_corner_candidates_not_kept(ContactCandidates& candidates) const;
  // The three rules above, in their order.
  void apply_bond_rules(ContactCandidates& candidates) const;
  // bonds.cpp: whether the bonds broken in the try under way give back a contact that the bond
  // rules dropped at its detection, while they were intact, and whose vertex the try's motion
  // took into the edge's block.
  bool breaks_let_corners_in(const Eigen::VectorXd& d) const;
  // A contact that touches at the start takes the initial stress's force across its faces: its
  // multiplier the normal force, its shear reference moved so that its spring holds the shear.
  void preload_contact(ActiveContact& c) const;
  void linearise_contact(ActiveContact& c) const;
  void linearise_closed_contact(ActiveContact& c) const;
  // Why a step's solve did not settle, if it did not.
  // interrupted: interrupt_check_ said stop before a pass (the step is to be abandoned).
  // thrown: a solve moved a vertex farther than half the model's height (solve_step).
  enum class Unsettled { no, contact_states, contact_forces, thrown, interrupted };
  Unsettled solve_step(double dt, Eigen::VectorXd& d, StepReport& report);
  void assemble_blocks(double dt, Matrix6Array& k_base, Eigen::VectorXd& f_base) const;
  void factor_with_contacts();
  Eigen::VectorXd assemble_contact_rhs(const Eigen::VectorXd& f_base) const;
  // The loads of the closed contacts closed_[begin … end − 1] (their multipliers, penalties and
  // friction), into f.
  void add_contact_loads(std::size_t begin, std::size_t end, Eigen::VectorXd& f) const;
  // The change of the load when the sliding contacts' friction goes from the normal forces
  // `from` to `to` (in the order of `sliding`).
  Eigen::VectorXd friction_load_change(const std::vector<ActiveContact*>& sliding, const Eigen::VectorXd& from,
                                       const Eigen::VectorXd& to) const;
  Vector6 block_unknowns(const Eigen::VectorXd& d, int dof) const;
  double compute_penetration(const ActiveContact& c, const Eigen::VectorXd& d) const;
  double compute_shear(const ActiveContact& c, const Eigen::VectorXd& d) const;
  double compute_normal_force(const ActiveContact& c, double penetration) const;
  double compute_shear_strength(const ActiveContact& c, double normal_force) const;
  // The state a contact closes in: sliding on a joint that has no shear strength at any normal
  // force (no friction, no cohesion, no intact bond), locked otherwise (System::update_state).
  ContactState closed_state(const ContactKey& key) const;
  // The closed contacts' penetrations and normal forces under the solution d, into their
  // records; the deepest penetration and the largest normal force (in size).
  struct ContactForceExtent {
    double deepest = 0.0;
    double force_scale = 0.0;
  };
  ContactForceExtent update_contact_forces(const Eigen::VectorXd& d);
  // Moves contact c to the state the solution d puts it in; whether it changed. `band` is the
  // hysteresis in length, `tension_allowance` the pull a closed contact may carry past T l.
  bool update_state(ActiveContact& c, const Eigen::VectorXd& d, double band, double tension_allowance) const;
  // The largest distance a vertex moves under the block unknowns `change` (first order).
  double largest_vertex_motion(const Eigen::VectorXd& change) const;
  void commit_step(const Eigen::VectorXd& d, double dt);
  // What a try does when its Lagrangian passes run out (lagrangian_limits.cpp). The closed
  // contacts standing off their edges by more than the penetration tolerance open; bit 1 of
  // the result: some opened, bit 2: one of them had changed state already in this step.
  char open_contacts_standing_off();
  // λ ← λ + p d on every closed contact (their normal forces); once mixing_multipliers_, from
  // the pass kPlainLagrangianPasses on, mixed with the passes before by Anderson's rule.
  void update_multipliers(int pass, numerics::AndersonAccelerator& mixing);
  static constexpr int kPlainLagrangianPasses = 10;
  // The penalty of a closed contact's normal spring in the try under way: its springs' p, or
  // once stiff_normal_springs_, under the augmented Lagrangian, raised to
  // kInertiaOverPenalty × 2M/Δt² of the lighter of its movable blocks, at most
  // kMostPenaltyRaise × p (lagrangian_limits.cpp).
  double normal_spring(const ActiveContact& c) const;
  double stiffened_normal_spring(const ActiveContact& c) const;
  // A block's inertia in the step under way, 2M/Δt² (M its mass a unit thickness).
  double step_inertia(const Block& block) const;
  // In a model without bonds, some closed contact overlaps past the tolerance where a
  // stiffened normal spring would be stiffer than its p.
  bool overlaps_slowed_by_inertia() const;
  static constexpr double kInertiaOverPenalty = 10.0;
  static constexpr double kMostPenaltyRaise = 100.0;
  // Some closed contact overlaps past the tolerance, and none of them is held by its blocks'
  // inertia: 2M/Δt² ≤ its normal spring's penalty for each movable block of each.
  bool overlaps_held_by_the_blocks_around() const;
  // Whether no closed contact overlaps its edge by more than a step whose passes no longer move
  // the blocks may hold: the tolerance × `growth` and 1e-6 of the tolerance more, or the
  // overlap it started with, up to twice the tolerance.
  bool overlaps_held(double growth) const;
  // The multipliers of a try that stalled with its overlaps at the tolerance, for the next
  // try at the step, given to the contacts closed in both.
  void keep_tried_multipliers();
  // A try whose passes stalled: the closed contacts within the tolerance take back the
  // multipliers they started the open–close pass with, and every closed contact its force
  // under the solution d (lagrangian_limits.cpp).
  ContactForceExtent undo_stalled_updates_within_tolerance(const Eigen::VectorXd& d);
  void start_from_tried_multipliers();
  // After commit_step: the step's unbalanced force into `report` (unbalanced_force.cpp).
  void measure_unbalanced_force(const std::vector<Point>& step_translation, double dt, StepReport& report) const;
  // Before commit_step: how long the blocks that move freely in the step d take to meet
  // anything, into free_drift_ and `report` (free_drift.cpp).
  void measure_free_drift(const Eigen::VectorXd& d, StepReport& report);

  std::vector<Block> blocks_;
  FreeDrift free_drift_;  // of the last step
  std::vector<Material> materials_;
  std::vector<Eigen::Matrix3d> elasticity_;
  // A joint type's strengths as the contact laws read them.
  struct JointStrength {
    double tan_friction = 0.0;
    double cohesion = 0.0;          // Pa
    double tensile_strength = 0.0;  // Pa
    double fracture_energy = 0.0;   // J/m2
  };
  static JointStrength strength_of(const Joint& j);
  std::vector<JointStrength> joints_;           // by type (ModelDefinition::joint, joint_types)
  std::vector<std::vector<int>> edge_joints_;   // per block, per edge: the type; empty: 0
  // The joint type of a contact: that of the edge its vertex touches; on a bonded edge that
  // no intact bond holds the vertex's block to (broken, or a third block's), the type without
  // tension or cohesion.
  const JointStrength& joint_of(const ContactKey& key) const {
    const std::vector<int>& edges = edge_joints_[static_cast<std::size_t>(key.block_j)];
    const std::size_t type = edges.empty() ? 0 : static_cast<std::size_t>(edges[static_cast<std::size_t>(key.edge)]);
    return bond_of(key) >= 0 && !is_intact_bond(key) ? broken_joints_[type] : joints_[type];
  }
  // The bond a contact lies across: that of the edge its vertex touches, when the vertex's block
  // is the bond's other sub-block; −1 for the vertex of a third sub-block that meets the face
  // at its end (four sub-blocks meet at a point along a crack's line): no bond holds it there.
  int bond_across(const ContactKey& key) const {
    const int bond = bond_of(key);
    if (bond < 0) return -1;
    const std::array<BondSide, 2>& sides = bond_sides_[static_cast<std::size_t>(bond)];
    return sides[0].block == key.block_i || sides[1].block == key.block_i ? bond : -1;
  }
  // The bond of the edge a contact's vertex touches, or −1.
  int bond_of(const ContactKey& key) const {
    const std::vector<int>& bonds = edge_bonds_[static_cast<std::size_t>(key.block_j)];
    return bonds.empty() ? -1 : bonds[static_cast<std::size_t>(key.edge)];
  }
  // The penalty of a contact's springs: p, or on a bonded face p l / l̄ (l its tributary
  // length, l̄ the bonds' mean: a stiffness per unit length, so that a face of any length
  // carries the traction the rock would; bonds.cpp).
  double contact_stiffness(const ContactKey& key, double length) const {
    return bond_of(key) < 0 ? penalty_ : penalty_ * std::max(length, 0.05 * bond_reference_length_) / bond_reference_length_;
  }
  bool is_intact_bond(const ContactKey& key) const {
    const int bond = bond_across(key);
    return bond >= 0 && bond_broken_[static_cast<std::size_t>(bond)] == 0;
  }
  // dda/bonds.cpp: the bonds' faces paired from the definition (throws std::invalid_argument
  // for an id not on exactly two edges of two blocks); the bonds whose face the solution d
  // overloads broken (pending until the step commits; whether any broke); a retried step's pending breaks
  // undone; the committed step's recorded.
  void setup_bonds(const std::vector<BlockDefinition>& blocks, const std::vector<int>& broken_at_start);
  bool break_overloaded_bonds(const Eigen::VectorXd& d);
  void undo_pending_bond_breaks();
  void record_pending_bond_breaks();
  struct BondSide {
    int block = -1;
    int edge = -1;
  };
  std::vector<std::array<BondSide, 2>> bond_sides_;  // by bond id
  std::vector<std::vector<int>> edge_bonds_;          // per block, per edge: the bond; empty: none
  std::vector<char> bond_broken_;                     // by bond id: 0 intact, 1 broken, 2 softening
  int breakable_bonds_ = 0;                           // the ids below it; from it on, the zone faces
  std::vector<int> broken_at_start_;                  // ModelDefinition::broken_bonds
  std::vector<JointStrength> broken_joints_;          // by type: tan φ only
  std::vector<std::pair<int, BondFailure>> pending_breaks_;  // broken in the step under way
  std::vector<std::pair<int, BondFailure>> last_cut_try_breaks_;  // break_bonds_of_last_cut_try's
  std::vector<BondBreak> bond_breaks_;
  double bond_reference_length_ = 1.0;  // m, l̄: half the bonds' mean face length
  // dda/softening_bonds.cpp: the bonds softening, with their ends' peak openings; those that
  // started to soften in the step under way; the tractions the pass's loads were made with.
  std::vector<SofteningBond> softening_;
  std::vector<int> pending_softening_;
  std::vector<std::array<double, 2>> cohesion_used_;  // by softening_'s index
  // The tractions the next pass's loads take (Anderson-mixed; empty: read from the opening),
  // their mixing, and the passes since the fixed point's map last changed.
  Eigen::VectorXd cohesion_next_;
  numerics::AndersonAccelerator cohesion_mixing_;
  int cohesion_passes_ = 0;
  void restart_cohesive_mixing();
  bool release_most_open_bond(const Eigen::VectorXd& d);
  std::array<double, 2> opening_after(int bond, const Eigen::VectorXd& d) const;
  void add_cohesive_loads(const Eigen::VectorXd& d, Eigen::VectorXd& f);
  enum class CohesionChange { none, moved, broke };
  // `contacts_changed`: some contact changed state in the pass (the map of the fixed point changed).
  CohesionChange settle_cohesive_loads(const Eigen::VectorXd& d, bool contacts_changed);
  void start_softening(int bond);
  void undo_pending_softening();
  void commit_softening();
  Settings settings_;
  std::vector<TrackedPoint> fixed_points_;
  std::vector<PointLoad> point_loads_;  // point = current position
  std::vector<TrackedPoint> load_points_;
  std::vector<PrescribedDisplacement> displacements_;
  std::vector<TrackedPoint> displacement_points_;
  std::vector<EdgeTraction> tractions_;
  std::vector<TrackedPoint> measured_;
  struct RollerPoint {
    Roller roller;
    Point initial;        // the vertex's position at the start
    double relief = 0.0;  // N/m: the fluid's push on its faces at the start (relieve_start_loads)
  };
  std::vector<RollerPoint> rollers_;
  std::optional<StressField> initial_stress_;
  // The contacts found touching at the first step start carrying the initial stress, less the
  // fluid's push on their faces when relieve_start_loads gave one.
  bool preload_new_contacts_ = false;
  FaceShare start_face_share_;
  std::vector<std::vector<Point>> vertex_forces_;
  std::unique_ptr<LinearSolver> solver_;

  // The step's matrix as the solver takes it, kept between calls: the blocks' own terms
  // (diagonal blocks, assembled once a step) and the contact springs (once a pass).
  struct AssemblyBuffers {
    BlockMatrix matrix;
    RankOneTerms terms;
  };
  AssemblyBuffers assembly_;
  // Contact detection's lists, kept from step to step: fresh ones cost their page faults
  // every step.
  struct DetectionBuffers {
    std::vector<std::span<const Point>> polygons;  // the blocks', in block order
    std::vector<char> fixed;
    ContactCandidates candidates;
    ContactCandidates before_bond_rules;  // the search's, kept where bonds may break
  };
  ContactSearch contact_search_{0.0, 0.0};  // made with the contact distance
  DetectionBuffers detection_;

  // The contacts of the last step, in key order.
  using KeyedRecord = std::pair<ContactKey, ContactRecord>;
  std::vector<KeyedRecord> records_;
  std::vector<ActiveContact> active_;  // some 300 bytes each
  std::vector<int> closed_;            // active_'s closed contacts this pass, ascending
  // The closed contacts' multipliers at the end of a try of this step that stalled with its
  // overlaps at the tolerance, in key order; empty when the last try did not.
  std::vector<std::pair<ContactKey, double>> tried_multipliers_;
  std::vector<double> pass_start_multipliers_;  // of closed_, at the open–close pass's start
  int unknown_count_ = 0;
  double time_ = 0.0;
  double dt_ = 0.0;
  std::optional<double> held_load_time_;
  double penalty_ = 0.0;
  double fixed_stiffness_ = 0.0;
  double model_size_ = 0.0;
  double allowed_displacement_ = 0.0;
  double contact_distance_ = 0.0;
  double penetration_tolerance_ = 0.0;
  // The augmented Lagrangian's passes allowed in this attempt at a step: max_lagrangian_iterations,
  // twice that once its forces failed to settle (System::step).
  int lagrangian_limit_ = 0;
  bool mixing_multipliers_ = false;  // this step's tries mix their multipliers (lagrangian_limits.cpp)
  bool stiff_normal_springs_ = false;  // this step's tries stiffen their normal springs (normal_spring)
  std::function<bool()> interrupt_check_;  // set_interrupt_check
  // Undoes what the step under way changed (its bonds broken, its cuts of the time step, which
  // began at `first_time_step`) and throws StepInterrupted.
  [[noreturn]] void abandon_interrupted_step(double first_time_step, const StepReport& report);
  // What the last step whose contact forces did not settle left unsettled, for its error.
  std::string unsettled_forces_;
  double thrown_motion_ = 0.0;  // how far the solve that threw blocks moved a vertex (m)
  std::string describe_unsettled_forces(bool penetration_ok, double friction_change, double force_scale) const;
  // A contact's change of state in open–close pass `pass` (unsettled_states.cpp): noted before
  // changed_in_step is set, so that a change back is told from a first change.
  static void note_state_change(ActiveContact& c, int pass, ContactState from, double penetration_from);
  // What the last step whose contact states did not settle left unsettled, for its error: the
  // contacts that changed state in its last pass `last_pass` (−1: it ran none).
  std::string unsettled_states_;
  std::string describe_unsettled_states(int last_pass) const;
  int open_close_pass_ = -1;  // the pass under way in solve_step
};

}  // namespace hydrodda::dda
