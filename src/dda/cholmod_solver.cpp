// CHOLMOD behind LinearSolver: the only file that includes Eigen/CholmodSupport.
#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Eigen/OrderingMethods>

#include "dda/linear_solver.hpp"

namespace hydrodda::dda {
namespace {

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    // We permute the matrix ourselves (block AMD); CHOLMOD keeps that order.
    cholmod_.cholmod().nmethods = 1;
    cholmod_.cholmod().method[0].ordering = CHOLMOD_NATURAL;
  }

  void factor(const SparseMatrix& lower, int block_count,
              const std::vector<std::pair<int, int>>& block_pairs) override {
    const bool same_pattern = analysed_ && block_count == block_count_ &&
                              block_pairs == block_pairs_;
    if (!same_pattern) compute_ordering(block_count, block_pairs);
    permuted_.resize(lower.rows(), lower.cols());
    permuted_.selfadjointView<Eigen::Lower>() =
        lower.selfadjointView<Eigen::Lower>().twistedBy(permutation_);
    if (!same_pattern) {
      cholmod_.analyzePattern(permuted_);
      analysed_ = true;
    }
    cholmod_.factorize(permuted_);
    if (cholmod_.info() != Eigen::Success)
      throw std::runtime_error("DDA: the global stiffness matrix is not positive definite");
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const override {
    Eigen::VectorXd permuted_rhs = permutation_ * rhs;
    Eigen::VectorXd x = cholmod_.solve(permuted_rhs);
    return permutation_.inverse() * x;
  }

 private:
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
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> block_inverse;
    Eigen::AMDOrdering<int>()(graph, block_inverse);
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse(6 * block_count);
    for (int b = 0; b < block_count; ++b)
      for (int k = 0; k < 6; ++k) inverse.indices()[6 * b + k] = 6 * block_inverse.indices()[b] + k;
    permutation_ = inverse.inverse();
    block_count_ = block_count;
    block_pairs_ = block_pairs;
  }

  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> cholmod_;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation_;
  SparseMatrix permuted_;
  bool analysed_ = false;
  int block_count_ = -1;
  std::vector<std::pair<int, int>> block_pairs_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace hydrodda::dda
