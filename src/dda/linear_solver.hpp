#pragma once
// The solver interface the DDA step factors and solves through, so that an iterative or a
// distributed solver can stand in for the direct one.

#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Sparse>

namespace hydrodda::dda {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Factor the symmetric positive definite matrix given by its lower triangle. It is made of
  // 6×6 blocks; block_pairs (i < j, sorted) lists its off-diagonal block pattern.
  virtual void factor(const SparseMatrix& lower, int block_count,
                      const std::vector<std::pair<int, int>>& block_pairs) = 0;
  // Solve with the last factorisation.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const = 0;
};

// CHOLMOD through Eigen, ordered by AMD on the block graph (6× fewer nodes than the scalar
// graph) and re-analysed only when the block pattern changes.
std::unique_ptr<LinearSolver> make_cholmod_solver();

}  // namespace hydrodda::dda
