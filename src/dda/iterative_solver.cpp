// Preconditioned conjugate gradients behind LinearSolver, warm-started from the last
// solution: consecutive DDA solves (Lagrangian updates, open–close iterations, successive
// steps) differ little, so a few iterations suffice where a direct factorisation of a 2D
// block graph costs O(N^1.5). The preconditioner is the exact inverse of each 6×6 diagonal
// block (block Jacobi).
#include <stdexcept>

#include <Eigen/Dense>

#include "dda/linear_solver.hpp"

namespace hydrodda::dda {
namespace {

class ConjugateGradientSolver final : public LinearSolver {
 public:
  ConjugateGradientSolver(double tolerance, int max_iterations)
      : tolerance_(tolerance), max_iterations_(max_iterations) {}

  void factor(const BlockMatrix& base, const RankOneTerms& springs) override {
    add_springs(base, springs, matrix_);
    inverse_blocks_.resize(matrix_.block_count);
    for (int b = 0; b < matrix_.block_count; ++b) inverse_blocks_[b] = matrix_.diagonal[b].inverse();
  }

  SolverCounts counts() const override { return counts_; }
  void reset() override { guess_.resize(0); }

  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const override {
    ++counts_.solves;
    guess_ = solve_to(rhs, guess_, tolerance_);
    return guess_;
  }

  Eigen::VectorXd estimate(const Eigen::VectorXd& rhs, double relative) const override {
    ++counts_.estimates;
    return solve_to(rhs, Eigen::VectorXd(), relative);
  }

 private:
  // x with ‖b − A x‖ ≤ tolerance ‖b‖, by CG from `guess`.
  Eigen::VectorXd solve_to(const Eigen::VectorXd& b, const Eigen::VectorXd& guess, double tolerance) const {
    Eigen::VectorXd x;
    const int iterations = numerics::solve_by_conjugate_gradients(
        [this](const Eigen::VectorXd& v, Eigen::VectorXd& y) { matrix_.multiply(v, y); },
        [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { precondition(r, z); }, b, guess, tolerance,
        max_iterations_, x, counts_.iterations);
    if (iterations < 0) throw std::runtime_error("DDA: conjugate gradients did not converge");
    return x;
  }

  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
    z.resize(r.size());
    for (std::size_t b = 0; b < inverse_blocks_.size(); ++b)
      z.segment<6>(6 * b).noalias() = inverse_blocks_[b] * r.segment<6>(6 * b);
  }

  double tolerance_;
  int max_iterations_;
  BlockMatrix matrix_;
  std::vector<Eigen::Matrix<double, 6, 6>> inverse_blocks_;
  mutable Eigen::VectorXd guess_;
  mutable SolverCounts counts_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_conjugate_gradient_solver(double tolerance, int max_iterations) {
  return std::make_unique<ConjugateGradientSolver>(tolerance, max_iterations);
}

}  // namespace hydrodda::dda
