#pragma once
// The staggered HYDRO–DDA loop (the paper's Fig. 2, DESIGN.md §2.3). Each pass:
//   porosity (clip the current blocks) → permeability → flow solve → pressures
//   → fluid forces (faces: (1 − α) p, inside: −α ∇p) → mechanics (a set number of DDA steps)
//   → converged?
// The convergence norms are the changes between passes of the heads (relative to the range of
// the heads, so that no datum enters) and of the blocks' displacements; both are measured every
// pass, and `converged` is only ever set from them, never while the fluid load is still being
// ramped. The caller bounds the number of passes and stops when a pass reports convergence.
// With relaxation, heads and pressures are relaxed; the fluxes and boundary flows reported are
// those of the pass's own solve.

#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "coupling/boundary_gaps.hpp"
#include "coupling/embedded_joints.hpp"
#include "coupling/float_secant.hpp"
#include "coupling/fixed_stress_step.hpp"
#include "coupling/load_ramp.hpp"
#include "coupling/loop_acceleration.hpp"
#include "coupling/pass_loop.hpp"
#include "coupling/pass_report.hpp"
#include "coupling/pass_storage.hpp"
#include "coupling/permeability_model.hpp"
#include "coupling/porosity.hpp"
#include "coupling/pressure_forces.hpp"
#include "coupling/seepage_forces.hpp"
#include "dda/system.hpp"
#include "hydro/darcy_solver.hpp"
#include "mesh/triangle_mesh.hpp"
#include "numerics/anderson.hpp"

namespace hydrodda::coupling {

struct LoopSettings {
  double tolerance = 1.0e-4;
  double relaxation = 1.0;        // heads: h ← ω h_new + (1 − ω) h_old (with Aitken: the first ω)
  // Aitken: ω adapted from pass to pass from the last two head updates; Anderson: the heads
  // mixed from the last anderson_depth passes (StaggeredLoop::relax).
  Acceleration acceleration = Acceleration::none;
  int anderson_depth = 5;
  // The fluid forces of pass k are r_k = min(1, k / ramp_passes) of the way to the full ones,
  // from none (whole) or from still water's (overpressure; load_ramp.hpp); no pass before the
  // first at full load counts as converged.
  int ramp_passes = 1;
  // > 1: the first pass puts the load on at once (ramp_passes = 1), and if it moves the blocks
  // from where they started by more than the tolerance's share of the allowed step displacement
  // (they stood in no equilibrium with it: an in-situ stress under still water), the pass is run
  // again with the load ramped over this many passes (StaggeredLoop::ramp_if_the_load_moved).
  int ramp_if_moved = 0;
  RampedLoad ramped_load = RampedLoad::whole;
  int steps_per_pass = 100;       // DDA steps run in each pass
  // Then up to this many more, until the blocks are at rest (dda::System::is_at_rest);
  // 0: none. A pass that ends with them still moving does not count as converged. It stops
  // sooner once steps_per_pass steps in a row have each moved a block freely that cannot come
  // to rest within the steps left (coupling/settling_watch.hpp).
  int settle_steps = 0;
  // A loop whose change (the larger of the two norms) grew this many passes in a row, and by
  // diverging_growth over them, is reported as diverging (0 passes: never). A converging
  // iteration may grow for a few passes (the six-block up-down case grows 2x over 3) but not
  // tenfold over five.
  int diverging_passes = 5;
  double diverging_growth = 10.0;
  PermeabilityModel permeability;
  // Asked before every DDA step: true abandons the pass (PassInterrupted), so that a long pass
  // does not hold up an interrupt until its end. Unset: never.
  std::function<bool()> stop_requested;
  // Per element: a permeability the scenario imposes (flow regions, joint barriers' strips), or
  // none; empty: none anywhere. A joint's transmissivity does not add to it.
  std::vector<std::optional<double>> fixed_permeability;
  // Per element: its material's own matrix `permeability`, or none (the porosity law's k_m);
  // empty: none anywhere. Under the imposed one; a joint's transmissivity adds to it.
  std::vector<std::optional<double>> material_permeability;
  // Per block: Biot's coefficient α in [0, 1] (seepage_forces.hpp). Empty: 1 for every block.
  std::vector<double> biot_coefficients;
  // Joints as embedded fractures (embedded_joints.hpp), when the scenario gives their hydraulic
  // aperture: the network the blocks were cut as (the DDA system's block order) and each
  // fracture's law (its joint type's).
  // With bonded sub-blocks, the network's fracture ids from first_bond_fracture on are the
  // bonds' faces (EmbeddedJoints): each conducts once the DDA has it broken.
  struct Joints {
    geometry::BlockNetwork network;
    JointApertureLaws laws;
    int first_bond_fracture = -1;
  };
  std::optional<Joints> joints;
  // The fluid's stiffness within the pass (pass_storage.hpp): each pass's flow a backward-Euler
  // step in pseudo-time from the last pass's heads, the convergence judged on the steady
  // solve's. Unset: every pass's flow is the steady solve.
  std::optional<PseudoTimeSettings> pseudo_time;
  // A coupled transient run (fixed_stress_step.hpp): each pass is an iteration of the time step
  // begun by begin_time_step(), its flow the fixed-stress step from the step's start. Unset:
  // steady passes.
  std::optional<FixedStressSettings> fixed_stress;
};

// Thrown by run_pass when LoopSettings::stop_requested says so; the pass is not counted and the
// blocks are back where the last finished pass left them.
struct PassInterrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// How the pass-to-pass change has grown lately: passes in a row whose change (the larger norm)
// grew, the change before they started and the last one. Passes 1 and 2 never count: the
// first change is 1 by definition and the second has nothing comparable before it. Nor does a
// pass whose change, or the one before, took in a rise of the load (`ramp_passes`): a load
// that rises pass after pass moves the blocks more each time, and that is no divergence.
struct ChangeGrowth {
  int passes = 0;
  double base = 0.0;
  double last = 0.0;
  void add(double change, int iteration, int ramp_passes = 1);
  // A new load: the changes before it are another problem's, and growth counts again from the
  // change of the pass after the next, which compares two passes under the new load.
  void restart() { *this = ChangeGrowth{0, 0.0, std::numeric_limits<double>::infinity()}; }
  bool diverging(int passes_needed, double factor) const {
    return passes_needed > 0 && passes >= passes_needed && last >= factor * base;
  }
};

// The loop's state between passes as plain data, for checkpoints: with the DDA system's state
// it is all a later pass reads.
struct LoopState {
  int iterations = 0;                   // passes finished
  hydro::FlowSolution flow;             // the last pass's (relaxed) solution; empty before any
  std::vector<double> previous_heads;   // for the head norm (and relaxation)
  std::vector<double> heads_two_back;   // for head_change_two_passes
  std::vector<Point> previous_displacements;  // for the displacement norm
  ChangeGrowth growth;                  // for the divergence rule
  // Aitken's state: the last head update h̃ − h_old and the ω it was applied with.
  std::vector<double> previous_update;
  double relaxation = 1.0;
  // Anderson's history, oldest first: each pass's residual G(x) − x and image G(x), x the heads
  // and pressures the pass started from, G(x) its solve (numerics::AndersonAccelerator::Pass).
  std::vector<std::vector<double>> anderson_residuals, anderson_images;
  // The permeability whose factor the flow solver keeps for the next pass (null: none), shared
  // with the solver rather than copied.
  std::shared_ptr<const hydro::PermeabilityField> kept_factor_permeability;
  bool kept_factor_single_precision = false;  // that factor held in single precision
  // The fields the last pass ran on, per element (empty before any pass): every pass computes
  // them afresh from the blocks, but a run continued after its last pass (to write a summary the
  // disk could not take) has no pass left to, and shows these.
  PorosityField porosity;
  std::vector<double> permeability;
  std::vector<hydro::PermeabilityTensor> permeability_tensors;  // with joints; else empty
  // The float secant's memory of the groups free in the last pass (float_secant.hpp).
  std::vector<FloatSecant::Remembered> float_groups;
  // The passes the load rises over, as the first pass chose where the settings left it to it
  // (LoopSettings::ramp_if_moved); read back only after a pass.
  int ramp_passes = 1;
};

class StaggeredLoop final : public PassRunner {
 public:
  // Keeps references to the mesh and the DDA system, which must outlive the loop.
  StaggeredLoop(const mesh::TriangleMesh& mesh, hydro::DarcyProblem flow, dda::System& mechanics,
                LoopSettings settings);

  // Passes until `limits` or an end the passes measure (pass_loop.hpp), `observer` told after
  // each. A pass that throws is rethrown: abandon_pass() then puts the last finished one back.
  LoopResult run(const LoopLimits& limits, PassObserver& observer) { return run_passes(*this, limits, observer); }

  // One pass; throws on numerical failure (with what failed). After it the DDA system continues
  // from its state as exported (mechanics_state()), exactly as a run resumed there from a
  // checkpoint does: importing restarts the DDA linear solver, whose reused factors would
  // otherwise carry round-off history that no checkpoint holds. A pass the stop request
  // abandons (PassInterrupted) first puts back what it had changed, the DDA system included:
  // the loop and the blocks are then as the last finished pass left them (or as built).
  PassReport run_pass() override;
  // After a pass that threw: puts back what it had changed (its porosity, permeability and
  // heads included), so that the loop describes the last finished pass again, and the DDA
  // system as that pass left it (as built before the first), whether or not a pass was under way.
  void abandon_pass();

  // The state between passes, and its restoration (throws std::invalid_argument when the
  // sizes do not fit this mesh and system). The porosity and permeability in it are the last
  // pass's, for what is shown of that pass: every pass recomputes its own from the blocks.
  // With it, the DDA system's after the last finished pass (as built before the first).
  LoopState export_state() const;
  const dda::SystemState& mechanics_state() const { return last_mechanics_; }
  // The passes the fluid load rises over: the settings', or as the first pass chose
  // (LoopSettings::ramp_if_moved).
  int ramp_passes() const { return settings_.ramp_passes; }
  void import_state(LoopState state, const dda::SystemState& mechanics);

  // A coupled transient run (LoopSettings::fixed_stress): start_in_time() takes the heads at
  // t = 0 (given, or unset: the steady ones on the blocks as built) before any pass;
  // begin_time_step(Δt) makes the state now the start of a step of length Δt, whose iterations
  // the passes after it are (the fixed-stress flow step, then the mechanics under its
  // pressures). A pass converges only from the step's second iteration on: its first compares
  // with the last step's end. Throws std::logic_error without fixed_stress.
  void start_in_time(std::optional<hydro::FlowSolution> initial);
  void begin_time_step(double time_step);
  // The passes after it steady ones again, from the state now: what a time step that failed
  // asks of its loads (run/no_equilibrium_in_time.hpp). begin_time_step() takes up time again.
  void leave_time_step() { time_level_.reset(); }
  // Whether the passes are a time step's iterations (begin_time_step) or steady ones.
  bool in_time_step() const { return time_level_.has_value(); }
  double flow_reference_head() const { return darcy_.reference_head(); }

  // New values of the flow boundary conditions (DarcySolver::set_boundary_values), taken from
  // the next pass on: a loading path scripted between passes.
  void set_flow_boundary_values(std::span<const hydro::BoundaryCondition> boundaries) {
    darcy_.set_boundary_values(boundaries);
    begin_new_load();
  }
  // A load changed between passes (flow boundaries or tractions): the last passes' secant and
  // the divergence rule's growing changes are of another load.
  void begin_new_load() {
    float_secant_.forget();
    growth_.restart();
  }

  const hydro::FlowSolution& flow() const { return solution_; }
  const PorosityField& porosity() const { return porosity_; }
  // Per element: k (m²), or with joints the tensor's largest principal value (k where isotropic).
  const std::vector<double>& permeability() const { return permeability_; }
  // The elements whose fracture permeability the last pass capped (PermeabilityModel::
  // find_capped_elements), in order: what a run warns of.
  const std::vector<int>& capped_elements() const { return capped_elements_; }
  // With joints, the tensors the flow was solved with (one per element); empty without.
  const std::vector<hydro::PermeabilityTensor>& permeability_tensors() const { return permeability_tensors_; }
  // How far the blocks have left the fluid mesh now.
  MeshExcursion outside_mesh() const { return boundary_gaps_.find_excursion(current_blocks()); }
  // The joints' hydraulic aperture at each crossing of the last pass (none without joints).
  const std::optional<EmbeddedJoints>& joints() const { return joints_; }
  const std::vector<double>& joint_apertures() const { return joint_apertures_; }
  // The blocks farther from where they were built than their own size, farthest first.
  std::vector<EscapingBlock> blocks_beyond_their_size() const;
  // Passes run to their end (a pass that threw is not counted).
  int iterations() const override { return completed_; }
  // Seconds per phase over the passes that finished.
  struct PhaseSeconds {
    double porosity = 0.0, flow = 0.0, forces = 0.0, mechanics = 0.0;
  };
  const PhaseSeconds& phase_seconds() const { return seconds_; }
  // A flow solution exists (false until the first pass's solve succeeds).
  bool has_flow() const { return !solution_.head.empty(); }

  // Each block's displacement since the start (its centroid's).
  std::vector<Point> block_displacements() const;
  // How the blocks moved in the last pass, as the displacement norm saw it (empty `before`
  // until two passes have run since the loop began or took a state).
  struct PassMotion {
    std::vector<Point> before, after;  // each block's displacement at the end of the two passes
    double reference_length = 0.0;     // the norm's ℓ (displacement_change)
  };
  PassMotion last_pass_motion() const {
    return {pass_before_displacements_, previous_displacements_, mechanics_.allowed_step_displacement()};
  }

 private:
  std::vector<geometry::Polygon> current_blocks() const;
  // Per bond, nonzero where the DDA has it broken (empty without bonds).
  std::vector<char> broken_bonds() const;
  // Per block, per edge, nonzero on an intact bond: no face the fluid stands on (empty without bonds).
  std::vector<std::vector<char>> sealed_edges() const;
  std::vector<double> compute_joint_apertures(std::span<const geometry::Polygon> blocks) const;
  hydro::FlowSolution solve_flow(const std::vector<geometry::Polygon>& blocks);
  hydro::PermeabilityView update_permeability(const std::vector<geometry::Polygon>& blocks);
  PorosityField clip_blocks(const std::vector<geometry::Polygon>& blocks, BlockPieces* pieces) const;
  hydro::FlowSolution step_in_time(hydro::PermeabilityView permeability);
  std::vector<double> block_volumetric_strains() const;
  void set_joint_zone_matrix_permeability();
  void relax(hydro::FlowSolution& fresh);
  hydro::FlowSolution step_in_pseudo_time(double steady_change);
  std::vector<std::vector<Point>> fluid_forces(const std::vector<geometry::Polygon>& blocks,
                                               std::span<const double> pressure) const;
  void step_mechanics(PassReport& report);
  std::optional<double> ramp_if_the_load_moved();
  PassReport run_pass_ramped(double moved_at_once);
  void move_free_groups(PassReport& report, const std::vector<Point>& start_displacements);
  void measure_convergence(PassReport& report, double unrelaxed_head_change);
  void finish_pass(const PassReport& report);
  void accelerate_by_anderson(hydro::FlowSolution& fresh);

  // What a pass changes of the loop's state before its mechanics, as it was when the pass
  // began: given back when the pass is abandoned, let go when it finishes. Held by moving the
  // old values aside rather than by copying the state: at a million triangles a copy is
  // tens of megabytes beside the flow factorisation. The fields are held too (26 MB at a
  // million triangles), so that a pass that fails leaves the last finished one to report.
  struct PassStart {
    PorosityField porosity;
    std::vector<double> permeability;
    std::vector<hydro::PermeabilityTensor> permeability_tensors;
    std::vector<double> joint_apertures;
    bool flow_solved = false;  // the solution and relaxation below were set aside
    hydro::FlowSolution solution;
    std::vector<double> previous_update;
    double relaxation = 1.0;
    std::deque<numerics::AndersonAccelerator::Pass> anderson_history;
    std::shared_ptr<const hydro::PermeabilityField> kept_factor;
    bool kept_factor_single_precision = false;
    double pseudo_time_step = 0.0, last_steady_change = 0.0;
    int step_passes = 0;
    std::optional<GapSecant> step_gaps;  // the step's gap secant before this pass
  };
  std::optional<PassStart> pass_start_;

  const mesh::TriangleMesh& mesh_;
  dda::System& mechanics_;
  LoopSettings settings_;
  hydro::DarcySolver darcy_;
  std::shared_ptr<const ElementIndex> elements_;  // shared by the next three
  PorosityMapper porosity_mapper_;
  BoundaryGaps boundary_gaps_;      // the faces that lay on the domain boundary as built
  FacePressureLoads face_loads_;
  bool seepage_ = false;             // some block has α > 0
  std::optional<EmbeddedJoints> joints_;
  std::vector<double> joint_apertures_;
  std::vector<hydro::PermeabilityTensor> permeability_tensors_;  // with joints: the last pass's
  // The blocks over each element, for the seepage force: the last pass's, kept so that each
  // pass refills the same storage.
  BlockPieces pieces_;

  std::vector<double> block_sizes_;  // √(area) of each block as built
  int iteration_ = 0;   // passes started
  int completed_ = 0;   // passes finished
  PorosityField porosity_;
  std::vector<double> permeability_;
  std::vector<int> capped_elements_;
  hydro::FlowSolution solution_;
  std::vector<double> previous_heads_;
  std::vector<double> heads_two_back_;
  std::vector<Point> previous_displacements_;
  std::vector<Point> pass_before_displacements_;  // the same a pass earlier, for last_pass_motion
  ChangeGrowth growth_;
  std::vector<double> previous_update_;
  double relaxation_ = 1.0;
  numerics::AndersonAccelerator anderson_;
  double pseudo_time_step_ = 0.0;     // Δτ of the next pass's step (pass_storage.hpp)
  double last_steady_change_ = 0.0;   // the last pass's steady head change, for SER
  // Groups that meet nothing, moved between settling passes to where their net load vanishes
  // (float_secant.hpp); Σ Δt² over the pass's DDA steps. The secant's memory is in LoopState.
  FloatSecant float_secant_;
  double pass_squared_steps_ = 0.0;
  // The start of the time step under way (coupled transient runs): Δt, the heads h^n and the
  // skeleton's volumes ζ^n per element there, and the passes (iterations) of the step so far.
  struct TimeLevel {
    double time_step = 0.0;
    std::vector<double> heads;
    std::vector<double> zeta;
    int passes = 0;
    GapSecant gaps;  // the open gaps' own β (fixed_stress_step.hpp)
  };
  std::optional<TimeLevel> time_level_;
  // The DDA system after the last finished pass (as built before the first): what an
  // abandoned pass puts back, and what every pass's system continues from.
  dda::SystemState last_mechanics_;
  PhaseSeconds seconds_;
};

// The displacement norm: the largest distance a block's centroid moved between the passes over
// the larger of the largest displacement and a reference length ℓ (the loop passes DDA's
// allowed step displacement, max_displacement_ratio × half the model height):
//   max_b |u_b − u'_b| / max(max_b |u_b|, ℓ).
// Against the displacement alone a model that starts in equilibrium (in-situ stress, rollers)
// has no scale: u is tiny, and the ratio of two tiny numbers never falls. UDEC and 3DEC judge
// equilibrium by the unbalanced force against the applied forces, not against what has moved;
// ℓ plays that part, and with the default tolerance 1e-4 a pass whose blocks move less than
// 1e-4 ℓ (DDA's own contact penetration tolerance) has settled. 0 when nothing moved.
double displacement_change(const std::vector<Point>& current, const std::vector<Point>& previous,
                           double reference_length);

// The head norm: the root mean square of a − b over the range of a (max a − min a), the head
// drop the boundary conditions set (the discrete maximum principle puts the extremes on the
// boundary). Adding a constant to every head changes neither. 0 when nothing changed, 1 when a
// is uniform but changed.
double head_change(const std::vector<double>& current, const std::vector<double>& previous);

}  // namespace hydrodda::coupling
