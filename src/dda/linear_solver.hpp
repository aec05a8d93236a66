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
// graph), re-analysed only when the block pattern changes. A factor is reused as the
// preconditioner of conjugate gradients on later, nearby matrices for up to max_iterations
// iterations to ‖b − A x‖ ≤ tolerance ‖b‖; past that the matrix is refactored.
std::unique_ptr<LinearSolver> make_cholmod_solver(double tolerance = 1e-12,
                                                  int max_iterations = 25);

// Block-Jacobi preconditioned conjugate gradients, warm-started from the last solution;
// converged when ‖b − A x‖ ≤ tolerance ‖b‖, else it throws after max_iterations.
std::unique_ptr<LinearSolver> make_conjugate_gradient_solver(double tolerance = 1e-10,
                                                             int max_iterations = 5000);

}  // namespace hydrodda::dda
