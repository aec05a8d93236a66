#pragma once
// Whether a settling pass (coupling.settle) can stop before its blocks are at rest: when they
// cannot come to rest within the steps it has left (docs/coupling.md, "Passes that settle").

#include <vector>

#include "dda/free_drift.hpp"

namespace hydrodda::coupling {

// Watches a settling pass's DDA steps. In a step that leaves N more, a block b (dda::FreeDrift:
// T_b the steps it takes to land at the step's rates, ∞ if it meets nothing)
//   - comes to rest in time when T_b ≤ N, or when it is slowing into a rest: its displacement
//     in the step u_k against the last step's u_{k−1}; held at the ratio r = u_k/u_{k−1} < 1,
//     it moves less than `at_rest` a step after n = ln(at_rest/u_k)/ln r more steps, n ≤ N
//     (a block's first step in the pass counts as steady: r = 1);
//   - otherwise drifts when N < T_b < ∞: it lands only after the pass would end;
//   - otherwise meets nothing (T_b = ∞): rising towards a float or escaping, which only
//     stepping on shows.
// A step drifts when a block drifts in it and none meets nothing. The pass may stop once
// `in_a_row` steps in a row have drifted.
class SettlingWatch {
 public:
  SettlingWatch(int in_a_row, double at_rest) : in_a_row_(in_a_row), at_rest_(at_rest) {}
  // After a step (each block's drift in it) that left `steps_left` more in the pass.
  void observe(const dda::FreeDrift& drift, int steps_left);
  // Whether the last `in_a_row` steps drifted.
  bool cannot_come_to_rest() const { return drifting_steps_ >= in_a_row_; }
  // The block that drifted in the last step, the one landing last (−1: the step did not drift).
  int drifting_block() const { return drifting_block_; }
  int drifting_steps() const { return drifting_steps_; }

  // Whether a block moving u_now a step after u_before comes to rest within steps_left more
  // steps, slowing at their ratio.
  static bool slows_to_rest(double u_before, double u_now, double at_rest, int steps_left);

 private:
  int in_a_row_;
  double at_rest_;
  int drifting_steps_ = 0;
  int drifting_block_ = -1;
  std::vector<double> last_motion_;  // per block, in the last step (empty before the first)
};

}  // namespace hydrodda::coupling
