#pragma once
// What one coupling pass did and measured (StaggeredLoop::run_pass), as the loop over passes
// (pass_loop.hpp) and whatever records them read it.

#include <vector>

#include "coupling/boundary_gaps.hpp"

namespace hydrodda::coupling {

// A block that has moved farther than its own size, √(its area), while the loop still moves
// it: in a static analysis blocks in equilibrium move by their strains and by sliding to a new
// seat, not by their own size, so the load has no equilibrium the contacts and supports can
// give it.
struct EscapingBlock {
  int block = 0;
  double distance = 0.0;  // of its centroid from where it was built (m)
  double size = 0.0;      // √(its area) (m)
};

// What one pass did and measured.
struct PassReport {
  int iteration = 0;              // 1-based
  double time = 0.0;              // mechanics time at the end of the pass
  double head_change = 0.0;       // rms(h̃_k − h_{k−1}) / (max h̃_k − min h̃_k), h̃_k unrelaxed (1 on pass 1)
  // The same against the heads of two passes back (1 before pass 3): far below head_change
  // when the loop swings between two states.
  double head_change_two_passes = 1.0;
  // max_b |u_k − u_{k−1}| / max(max_b |u_k|, ℓ) over block centroids, ℓ DDA's allowed step
  // displacement (displacement_change below; 1 on the first pass)
  double displacement_change = 0.0;
  double largest_opening = 0.0;   // widest open contact gap (m)
  double mean_porosity = 0.0;
  double max_permeability = 0.0;
  double relaxation = 1.0;        // ω the heads were relaxed with in this pass
  double load_factor = 1.0;       // of the fluid forces, below 1 while ramped
  // > 0: this first pass was run again ramped, after the whole load at once had moved the
  // blocks this far (m) from their in-situ state (LoopSettings::ramp_if_moved).
  double moved_at_once = 0.0;
  int settling_steps = 0;         // DDA steps past steps_per_pass (LoopSettings::settle_steps)
  bool at_rest = true;            // false: settle_steps ran out with the blocks still moving
  // Settling stopped before settle_steps ran out (SettlingWatch): this block (−1: it did not)
  // moved freely in the pass's last step, not slowing, landing only after the steps left.
  int drifting_block = -1;
  // Whether the pass's last DDA step ran at the full mechanics.time_step, and the shortest
  // step of the pass. A step cut short moves the blocks little however far they are from
  // equilibrium, so a pass that ends on one does not count as converged.
  bool full_time_step = true;
  double shortest_time_step = 0.0;
  // Everything convergence asks but the full step: both norms under the tolerance at the full
  // load, the blocks at rest. Set without full_time_step, the steps cut short kept the pass
  // from counting.
  bool under_tolerance = false;
  MeshExcursion outside_mesh;     // how far the blocks had left the fluid mesh after the pass
  bool converged = false;
  // The change has grown LoopSettings::diverging_passes passes in a row.
  bool diverging = false;
  // Not converged and some blocks escape (farthest first): no equilibrium to converge to.
  std::vector<EscapingBlock> escaping;
  int growing_passes = 0;         // passes in a row whose change grew
  // What moved in the pass, to tell a loop whose contacts chatter from one still on its way
  // (docs/coupling.md, "Contacts that chatter"): the contacts whose state (open, locked,
  // sliding) at the pass's end differs from its start (a contact that appeared or went
  // counts); the joint crossings whose gauge read open at one end of the pass and closed at
  // the other; the largest change of a fluid force on a vertex against the largest fluid force;
  // the most open–close iterations a DDA step of the pass took, and how often its steps were cut.
  int contact_state_changes = 0;
  int joint_crossings_switched = 0;
  double fluid_load_change = 1.0;
  int most_open_close_iterations = 0;
  int step_cuts = 0;
  // Groups of blocks that met nothing in the pass, moved after it to where the secant of their
  // net load vanishes (float_secant.hpp), and the longest such shift (m).
  int groups_moved = 0;
  double longest_group_shift = 0.0;
  // Seconds per phase in this pass.
  double porosity_seconds = 0.0, flow_seconds = 0.0, forces_seconds = 0.0, mechanics_seconds = 0.0;
};

}  // namespace hydrodda::coupling
