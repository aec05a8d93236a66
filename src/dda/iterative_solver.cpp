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

  void factor(const BlockMatrix& base, const std::vector<RankOneTerm>& springs) override {
    matrix_ = add_springs(base, springs);
    const BlockMatrix& a = matrix_;
    inverse_blocks_.resize(a.block_count);
    for (int b = 0; b < a.block_count; ++b) inverse_blocks_[b] = a.diagonal[b].inverse();
    if (guess_.size() != a.size()) guess_ = Eigen::VectorXd::Zero(a.size());
  }

  SolverCounts counts() const override { return counts_; }
  void reset() override { guess_.resize(0); }

  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const override {
    ++counts_.solves;
    // Pseudocode (Saad, Iterative Methods, alg. 9.1): r = b − A x; z = M⁻¹ r; p = z;
    // repeat: α = rᵀz / pᵀAp; x += α p; r −= α A p; z = M⁻¹ r; β = r'ᵀz' / rᵀz; p = z + β p.
    const double b_norm = rhs.norm();
    Eigen::VectorXd x = guess_;
    if (b_norm == 0.0) return Eigen::VectorXd::Zero(rhs.size());
    Eigen::VectorXd q(rhs.size());
    matrix_.multiply(x, q);
    Eigen::VectorXd r = rhs - q;
    Eigen::VectorXd z = precondition(r);
    Eigen::VectorXd p = z;
    double rz = r.dot(z);
    int it = 0;
    for (; it < max_iterations_ && r.norm() > tolerance_ * b_norm; ++it) {
      matrix_.multiply(p, q);
      const double alpha = rz / p.dot(q);
      x += alpha * p;
      r -= alpha * q;
      z = precondition(r);
      const double rz_new = r.dot(z);
      p = z + (rz_new / rz) * p;
      rz = rz_new;
    }
    if (r.norm() > tolerance_ * b_norm)
      throw std::runtime_error("DDA: conjugate gradients did not converge");
    guess_ = x;
    counts_.iterations += it;
    return x;
  }

 private:
  Eigen::VectorXd precondition(const Eigen::VectorXd& r) const {
    Eigen::VectorXd z(r.size());
    for (std::size_t b = 0; b < inverse_blocks_.size(); ++b)
      z.segment<6>(6 * b).noalias() = inverse_blocks_[b] * r.segment<6>(6 * b);
    return z;
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
