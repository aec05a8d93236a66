// CHOLMOD behind LinearSolver: the only file that includes Eigen/CholmodSupport.
//
// Strategy (bench_dda showed that refactoring for every solve dominates the step; reusing
// the factor as a CG preconditioner took the 401-block wall from 13 to 8 ms a step):
// factor() only records the new matrix. solve() runs conjugate gradients on it, preconditioned
// by the last Cholesky factor, which belongs to a nearby matrix (same contacts, geometry a
// step or an open–close iteration older). When that factor is stale, CG stops making progress
// within a few iterations and the current matrix is factored (numerically only while the
// block pattern is unchanged) and solved directly.
//   solve(b): x = L⁻ᵀL⁻¹ b; repeat up to k times: CG update with M = LLᵀ
//             if ‖b − A x‖ > tol ‖b‖: factor A; x = A⁻¹ b
#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Eigen/OrderingMethods>

#include "dda/linear_solver.hpp"

namespace hydrodda::dda {
namespace {

using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver(double tolerance, int max_iterations)
      : tolerance_(tolerance), max_iterations_(max_iterations) {
    // We permute the matrix ourselves (block AMD); CHOLMOD keeps that order.
    cholmod_.cholmod().nmethods = 1;
    cholmod_.cholmod().method[0].ordering = CHOLMOD_NATURAL;
    // Simplicial LDLᵀ: on these very sparse 2D block graphs it beats the supernodal
    // factorisation with the reference BLAS (measured with bench_dda).
    cholmod_.setMode(Eigen::CholmodLDLt);
  }

  void factor(const SparseMatrix& lower, int block_count,
              const std::vector<std::pair<int, int>>& block_pairs) override {
    if (!has_ordering_ || block_count != block_count_) compute_ordering(block_count, block_pairs);
    pattern_changed_ = block_pairs != factored_pairs_;
    pending_pairs_ = block_pairs;
    permuted_.resize(lower.rows(), lower.cols());
    permuted_.selfadjointView<Eigen::Lower>() =
        lower.selfadjointView<Eigen::Lower>().twistedBy(permutation_);
    full_ = permuted_.selfadjointView<Eigen::Lower>();
    current_ = false;
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const override {
    const Eigen::VectorXd b = permutation_ * rhs;
    const double b_norm = b.norm();
    if (b_norm == 0.0) return Eigen::VectorXd::Zero(rhs.size());
    if (factored_ && !current_) {
      Eigen::VectorXd x;
      if (run_preconditioned_cg(b, b_norm, x)) return permutation_.inverse() * x;
    }
    if (!current_) refactor();
    Eigen::VectorXd x = cholmod_.solve(b);
    // One refinement step against round-off in the deep contact stiffness.
    x += cholmod_.solve(Eigen::VectorXd(b - full_ * x));
    return permutation_.inverse() * x;
  }

 private:
  // CG on the current matrix, preconditioned by the last factor (Saad, alg. 9.1).
  bool run_preconditioned_cg(const Eigen::VectorXd& b, double b_norm, Eigen::VectorXd& x) const {
    x = cholmod_.solve(b);
    Eigen::VectorXd r = b - full_ * x;
    if (r.norm() <= tolerance_ * b_norm) return true;
    Eigen::VectorXd z = cholmod_.solve(r);
    Eigen::VectorXd p = z;
    Eigen::VectorXd q(b.size());
    double rz = r.dot(z);
    for (int it = 0; it < max_iterations_; ++it) {
      q.noalias() = full_ * p;
      const double alpha = rz / p.dot(q);
      x += alpha * p;
      r -= alpha * q;
      if (r.norm() <= tolerance_ * b_norm) return true;
      z = cholmod_.solve(r);
      const double rz_new = r.dot(z);
      p = z + (rz_new / rz) * p;
      rz = rz_new;
    }
    return false;
  }

  void refactor() const {
    if (!factored_ || pattern_changed_) {
      cholmod_.analyzePattern(permuted_);
      factored_pairs_ = pending_pairs_;
      pattern_changed_ = false;
    }
    cholmod_.factorize(permuted_);
    if (cholmod_.info() != Eigen::Success)
      throw std::runtime_error("DDA: the global stiffness matrix is not positive definite");
    factored_ = true;
    current_ = true;
  }

  // AMD on the block graph (6× fewer nodes than the scalar one), expanded to the unknowns.
  // The graph is that of the first matrix; later contacts change the fill a little, not the
  // correctness.
  void compute_ordering(int block_count, const std::vector<std::pair<int, int>>& block_pairs) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(block_count + 2 * block_pairs.size());
    for (int b = 0; b < block_count; ++b) entries.emplace_back(b, b, 1.0);
    for (auto [i, j] : block_pairs) {
      entries.emplace_back(i, j, 1.0);
      entries.emplace_back(j, i, 1.0);
    }
    SparseMatrix graph(block_count, block_count);
    graph.setFromTriplets(entries.begin(), entries.end());
    Permutation block_inverse;
    Eigen::AMDOrdering<int>()(graph, block_inverse);
    Permutation inverse(6 * block_count);
    for (int b = 0; b < block_count; ++b)
      for (int k = 0; k < 6; ++k) inverse.indices()[6 * b + k] = 6 * block_inverse.indices()[b] + k;
    permutation_ = inverse.inverse();
    block_count_ = block_count;
    has_ordering_ = true;
  }

  double tolerance_;
  int max_iterations_;
  mutable Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> cholmod_;
  Permutation permutation_;
  SparseMatrix permuted_;
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> full_;
  bool has_ordering_ = false;
  int block_count_ = -1;
  std::vector<std::pair<int, int>> pending_pairs_;
  mutable std::vector<std::pair<int, int>> factored_pairs_;
  mutable bool pattern_changed_ = true;
  mutable bool factored_ = false;
  mutable bool current_ = false;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver(double tolerance, int max_iterations) {
  return std::make_unique<CholmodSolver>(tolerance, max_iterations);
}

}  // namespace hydrodda::dda
