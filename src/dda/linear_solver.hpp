#pragma once
// The solver interface the DDA step factors and solves through, so that an iterative or a
// distributed solver can stand in for the direct one.

#include <array>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Sparse>

#include "dda/block_matrix.hpp"
#include "numerics/conjugate_gradients.hpp"

namespace hydrodda::dda {

// One rank-one part w wᵀ of the matrix with w nonzero on at most two blocks: a contact
// spring, w = √p e. `id` names the part from call to call.
struct RankOneTerm {
  std::array<int, 5> id{};
  int block_a = -1, block_b = -1;  // −1: no entries there
  Eigen::Matrix<double, 6, 1> w_a = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> w_b = Eigen::Matrix<double, 6, 1>::Zero();

  // Whether w spans two different blocks: a block of w wᵀ off the diagonal.
  bool joins_two_blocks() const { return block_a >= 0 && block_b >= 0 && block_a != block_b; }
  // w's part on `block` (both ends added where the spring has it at both).
  Eigen::Matrix<double, 6, 1> part_on(int block) const {
    Eigen::Matrix<double, 6, 1> w = Eigen::Matrix<double, 6, 1>::Zero();
    if (block_a == block) w += w_a;
    if (block_b == block) w += w_b;
    return w;
  }
};

// The springs of a matrix: a large array (two per closed contact).
using RankOneTerms = std::vector<RankOneTerm>;

// The terms of `now` that `before` lacks (added) and those of `before` that `now` lacks
// (removed), both lists sorted by id, as a solver that follows the springs needs them. False,
// with the lists incomplete, as soon as there are more than `limit` changes.
bool find_changed_terms(const RankOneTerms& now, const RankOneTerms& before, std::size_t limit,
                        RankOneTerms& added, RankOneTerms& removed);

// An elimination order of base + Σ w wᵀ by approximate minimum degree on its block graph
// (order_by_minimum_degree), the springs joining the blocks they span.
std::vector<int> order_by_minimum_degree(const BlockMatrix& base, const RankOneTerms& springs);
// Whether base and the springs hold finite values only.
bool all_finite(const BlockMatrix& base, const RankOneTerms& springs);

// base + Σ w wᵀ over the springs as one block matrix: a block for each pair of blocks a
// spring joins.
BlockMatrix add_springs(const BlockMatrix& base, const RankOneTerms& springs);
// The same into `a`, whose memory is reused: a solver that factors again and again keeps one.
void add_springs(const BlockMatrix& base, const RankOneTerms& springs, BlockMatrix& a);

// y = (base + Σ w wᵀ) x, without assembling the springs.
void multiply_with_springs(const BlockMatrix& base, const RankOneTerms& springs,
                           const Eigen::VectorXd& x, Eigen::VectorXd& y);

// multiply_with_springs bit for bit, the block rows of y in one share per thread
// (numerics::for_each_share). Each share takes its rows' terms of the base and then every
// spring with an end in it, in the springs' order, so that each row sums the same terms in the
// same order as one multiply does, whatever the shares; a spring across two shares is dotted by
// both. Which springs touch which share is found once a matrix: conjugate gradients multiplies
// three or four times a solve, a fifth of a DDA step's work on the 1,601-block wall.
class SpringMatrixProduct {
 public:
  // The matrix base + Σ w wᵀ over `springs`, both read where they are until the next reset.
  void reset(const BlockMatrix& base, const RankOneTerms& springs);
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // Whether multiply shares the rows between threads.
  bool splits() const { return split_; }

 private:
  static constexpr int kEndA = 1, kEndB = 2;
  const BlockMatrix* base_ = nullptr;
  const RankOneTerms* springs_ = nullptr;
  bool split_ = false;  // enough springs, and two threads to share them
  // Per share of the rows: index << 2 | which ends (kEndA, kEndB) lie in it, in index order.
  std::vector<std::vector<int>> touching_;
};

// What a solver has done so far, for benchmarks and tests.
struct SolverCounts {
  long factorisations = 0;   // numeric factorisations from scratch
  long modified_terms = 0;   // rank-one updates and downdates of a kept factorisation
  long solves = 0;
  long iterations = 0;       // iterative-method iterations over all solves and estimates
  long estimates = 0;        // estimate() calls
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Factor the symmetric positive definite matrix A = base + Σ w wᵀ over `springs`. The
  // springs (sorted by id) are the rank-one parts that come and go between calls, the contact
  // springs: a solver that keeps a factorisation may follow the ones that appeared and
  // disappeared instead of starting again, and one that only multiplies by A need never
  // assemble them. The answer is always A's.
  virtual void factor(const BlockMatrix& base, const RankOneTerms& springs = {}) = 0;
  // The same without copying: solve() and estimate() may read `base` and `springs` themselves
  // until the next factor call or reset(), so the caller keeps both alive and unchanged for as
  // long as it solves with them (a large model's springs run to megabytes and come several
  // times a step, and a copy of them is as much fresh memory). A solver that keeps neither
  // copies, as factor() does.
  virtual void factor_borrowing(const BlockMatrix& base, const RankOneTerms& springs) { factor(base, springs); }
  // Solve with the last factorisation.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const = 0;
  // x with ‖rhs − A x‖ ≤ relative ‖rhs‖, from zero: the size of a small change to the
  // solution (what a change of load would move), not the solution itself. Leaves solve()'s
  // starting guess, and its rule for when to factor afresh, as they were; only a kept factor
  // that cannot reach even this tolerance is factored afresh here, as the next solve would.
  virtual Eigen::VectorXd estimate(const Eigen::VectorXd& rhs, double relative) const = 0;
  virtual SolverCounts counts() const = 0;
  // Forget every factor, ordering and starting guess kept from earlier matrices: the next
  // factor() and solve() behave as in a new solver. Solutions of a reused solver differ from
  // a new one's at round-off, so a run continued from a checkpoint restarts its solver, and so
  // does the run it must reproduce, at the same point.
  virtual void reset() = 0;
};

// The default: a block Cholesky factor (block_cholesky.hpp), kept from call to call, follows
// the contact springs by a low-rank Sherman–Morrison–Woodbury correction and serves as the
// preconditioner of conjugate gradients on the current matrix, started from the last
// solution, for up to max_iterations iterations to ‖b − A x‖ ≤ tolerance ‖b‖; when it stops
// helping, the matrix is factored again. Throws if the matrix is not positive definite.
std::unique_ptr<LinearSolver> make_block_factor_solver(double tolerance = 1e-12,
                                                       int max_iterations = 25);

// CHOLMOD's simplicial LDLᵀ, ordered by AMD on the block graph (6× fewer nodes than the
// scalar graph). The factor follows the contact springs by rank-one updates and downdates and
// serves as the preconditioner of conjugate gradients on the current matrix (which also moved
// with the geometry), started from the last solution, for up to max_iterations iterations to
// ‖b − A x‖ ≤ tolerance ‖b‖; when it stops helping, the matrix is factored again.
std::unique_ptr<LinearSolver> make_cholmod_solver(double tolerance = 1e-12,
                                                  int max_iterations = 25);

// Block-Jacobi preconditioned conjugate gradients, warm-started from the last solution;
// converged when ‖b − A x‖ ≤ tolerance ‖b‖, else it throws after max_iterations.
std::unique_ptr<LinearSolver> make_conjugate_gradient_solver(double tolerance = 1e-10,
                                                             int max_iterations = 5000);

}  // namespace hydrodda::dda
