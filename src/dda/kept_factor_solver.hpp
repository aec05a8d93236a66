#pragma once
// What the two solvers that keep a factor from call to call share (factor_solver.cpp,
// cholmod_solver.cpp): conjugate gradients preconditioned by the kept factor, a solve started
// from the last solution, an estimate started from zero, and the rule for when the factor has
// drifted too far from the matrix to keep. Each solver brings its own factor and its
// solve_to().

#include "dda/linear_solver.hpp"
#include "numerics/kept_factor.hpp"

namespace hydrodda::dda {

class KeptFactorSolver : public LinearSolver {
 public:
  KeptFactorSolver(double tolerance, int max_iterations) : tolerance_(tolerance), max_iterations_(max_iterations) {}

  // From the last solution: the solves of one step (Lagrangian and friction updates,
  // open–close passes) and of successive steps differ little, and starting there took the
  // 1,601-block wall from 14.6 to 8.8 iterations a step (bench_dda).
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const final {
    ++counts_.solves;
    if (rhs.norm() == 0.0) return Eigen::VectorXd::Zero(rhs.size());
    int iterations = 0;
    last_solution_ = solve_to(rhs, last_solution_, tolerance_, iterations);
    // The drift has grown past what pays: factor afresh before the next solve.
    if (iterations > numerics::kRefactorAfterIterations) stale_ = true;
    return last_solution_;
  }

  // From zero, leaving solve()'s starting guess and its refactoring rule alone.
  Eigen::VectorXd estimate(const Eigen::VectorXd& rhs, double relative) const final {
    ++counts_.estimates;
    if (rhs.norm() == 0.0) return Eigen::VectorXd::Zero(rhs.size());
    int iterations = 0;
    return solve_to(rhs, Eigen::VectorXd(), relative, iterations);
  }

  SolverCounts counts() const final { return counts_; }

 protected:
  // x with ‖b − A x‖ ≤ tolerance ‖b‖ (b ≠ 0), from `guess` when it has b's size; the CG
  // iterations it took (0 for a direct solve on a fresh factor).
  virtual Eigen::VectorXd solve_to(const Eigen::VectorXd& b, const Eigen::VectorXd& guess, double tolerance,
                                   int& iterations) const = 0;
  // No starting guess, and a factor to be made afresh: what reset() leaves.
  void forget_solution() {
    last_solution_.resize(0);
    stale_ = true;
  }

  const double tolerance_;
  const int max_iterations_;
  mutable bool stale_ = true;  // the kept factor, if any, is not to be used: factor afresh
  mutable SolverCounts counts_;

 private:
  mutable Eigen::VectorXd last_solution_;  // the starting guess of the next solve
};

}  // namespace hydrodda::dda
