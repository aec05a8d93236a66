#pragma once
// Anderson acceleration of a fixed-point iteration x = G(x): the DDA step's friction loads
// (dda/system.cpp) and the coupling loop's heads (coupling/staggered_loop.cpp) both mix their
// last few passes with it.
//
// The friction loads of sliding contacts depend on their normal forces, which depend on the
// solution the loads produce: a fixed point the step iterates, one linear solve per pass.
// Plain iteration x ← G(x) contracts slowly when many contacts slide together (a settling
// packing: a factor of about 0.6 a pass, thirty passes and more); Anderson's mixing of the
// last few passes reaches the same fixed point in a handful (bench_dda).
//
// Pseudocode (Walker & Ni, "Anderson acceleration for fixed-point iterations", SIAM J.
// Numer. Anal. 49 (2011), alg. AA, the unconstrained least-squares form):
//   f_k = G(x_k) − x_k
//   ΔF = [f_{i+1} − f_i], ΔG = [G(x_{i+1}) − G(x_i)] over the last m passes
//   γ  = argmin ‖f_k − ΔF γ‖₂
//   x_{k+1} = G(x_k) − ΔG γ
// With no history (the first pass, or after reset) it is the plain step x_{k+1} = G(x_k).

#include <deque>

#include <Eigen/Dense>

namespace hydrodda::numerics {

class AndersonAccelerator {
 public:
  explicit AndersonAccelerator(int depth = 5) : depth_(depth) {}

  // The next iterate from the current one and its image; both of one size from call to call
  // (a change of size starts the history again).
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g);

  // Forget the history: the map changed (the Lagrange multipliers moved), and mixing passes
  // of two maps would aim at neither's fixed point.
  void reset() { history_.clear(); }

  // The passes remembered, oldest first, and their restoration (for checkpoints).
  struct Pass {
    Eigen::VectorXd residual;  // G(x) − x
    Eigen::VectorXd image;     // G(x)
  };
  const std::deque<Pass>& history() const { return history_; }
  void restore(std::deque<Pass> history) { history_ = std::move(history); }

 private:
  int depth_;
  std::deque<Pass> history_;
};

}  // namespace hydrodda::numerics
