// Every backend of the sparse Cholesky interface (sparse_cholesky.hpp) solves the same
// symmetric positive definite systems to the same answer, and a factor refactored after its
// matrix's values changed is the fresh factorisation of the new matrix, bit for bit.
//
// The backends: CHOLMOD's analysis on the nested-dissection order with the program's own
// supernodal factorisation on two threads (FillOrdering::metis, the flow model's), and CHOLMOD's
// own ordering and factorisation (FillOrdering::automatic). The systems: a Darcy-like P1 matrix
// with a permeability contrast of 1e5 (large enough to be split in two halves, one ordered by
// the helper process), and a small matrix of 6×6 blocks as a DDA step makes (stiff contact
// springs across a wall of blocks).
//
// Tolerance, from the condition number. A Cholesky solve is backward stable: x̂ solves
// (A + ΔA) x̂ = b with ‖ΔA‖ ≤ c_n u ‖A‖, so ‖x̂ − x‖ / ‖x‖ ≤ κ₂(A) c_n u to first order (Higham,
// "Accuracy and Stability of Numerical Algorithms", 2nd ed. 2002, Thm 10.4 and §7.1). The
// worst-case constant c_n grows with n; what the sparse factors show in practice is a few tens
// (their columns hold tens of entries, not n). We allow c_n u = 64 u per solve, so two backends
// may differ by 2 · 64 u · κ₂(A), κ₂ computed (the block matrix: dense eigenvalues) or
// estimated (the Darcy matrix: Gershgorin's bound for λ_max, inverse iteration for λ_min).

#include "numerics/cholmod_solver.hpp"
#include "numerics/nested_dissection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

namespace hydrodda::numerics {
namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;
constexpr double kBackwardErrorPerSolve = 64 * kUnitRoundoff;  // c_n u, above

struct Backend {
  std::string name;
  std::function<std::unique_ptr<SparseCholesky>()> make;
};

std::vector<Backend> backends() {
  return {{"nested dissection, supernodal on two threads", [] { return make_cholmod_solver(FillOrdering::metis); }},
          {"CHOLMOD's own ordering and factorisation", [] { return make_cholmod_solver(FillOrdering::automatic); }}};
}

SparseMatrix upper_of(const std::vector<Eigen::Triplet<double>>& entries, int n) {
  SparseMatrix full(n, n);
  full.setFromTriplets(entries.begin(), entries.end());  // sums duplicates
  return full.triangularView<Eigen::Upper>();
}

// P1 flow on an nx × ny grid of unit squares, each cut into two right triangles, permeability
// 1 in fracture-like channels (every 15th row of cells, and a diagonal band) and 1e-5 in the
// matrix around them, times `channel_scale` in the channels. The element matrix of a right
// triangle with the right angle at r and legs to a and b is k/2 [[2, −1, −1], [−1, 1, 0],
// [−1, 0, 1]] in (r, a, b). Heads fixed on the left and right columns of nodes: the unknowns
// are the other nodes, and the matrix is the free nodes' block, symmetric positive definite.
SparseMatrix darcy_matrix(int nx, int ny, double channel_scale = 1.0) {
  const auto node = [nx](int i, int j) { return j * (nx + 1) + i; };
  const auto free_index = [nx](int i, int j) { return (i == 0 || i == nx) ? -1 : j * (nx - 1) + (i - 1); };
  const int unknowns = (nx - 1) * (ny + 1);
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](int node_a, int node_b, double value) {
    const int ia = free_index(node_a % (nx + 1), node_a / (nx + 1));
    const int ib = free_index(node_b % (nx + 1), node_b / (nx + 1));
    if (ia >= 0 && ib >= 0) entries.emplace_back(ia, ib, value);
  };
  const auto triangle = [&](int r, int a, int b, double k) {
    add(r, r, k);
    add(a, a, k / 2);
    add(b, b, k / 2);
    for (int other : {a, b}) {
      add(r, other, -k / 2);
      add(other, r, -k / 2);
    }
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const bool channel = j % 15 == 7 || std::abs(i - j) <= 1;
      const double k = channel ? channel_scale : 1e-5;
      triangle(node(i, j), node(i + 1, j), node(i, j + 1), k);              // right angle at (i, j)
      triangle(node(i + 1, j + 1), node(i, j + 1), node(i + 1, j), k);      // at (i + 1, j + 1)
    }
  return upper_of(entries, unknowns);
}

// A DDA step's matrix over a rows × rows wall of blocks: per block a 6×6 symmetric positive
// definite stiffness (elastic and inertial terms, order 1), and per pair of neighbours a few
// contact springs p w wᵀ, w on both blocks' 6 unknowns, p = 1e3: the penalty's contrast.
SparseMatrix block_matrix(int rows, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  const int blocks = rows * rows;
  std::vector<Eigen::Triplet<double>> entries;
  for (int b = 0; b < blocks; ++b) {
    Eigen::Matrix<double, 6, 6> m;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) m(r, c) = normal(random);
    const Eigen::Matrix<double, 6, 6> k = m * m.transpose() / 6 + Eigen::Matrix<double, 6, 6>::Identity();
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) entries.emplace_back(6 * b + r, 6 * b + c, k(r, c));
  }
  const auto spring = [&](int a, int b) {
    Eigen::Matrix<double, 12, 1> w;
    for (int r = 0; r < 12; ++r) w[r] = normal(random);
    const int base[2] = {6 * a, 6 * b};
    for (int r = 0; r < 12; ++r)
      for (int c = 0; c < 12; ++c) entries.emplace_back(base[r / 6] + r % 6, base[c / 6] + c % 6, 1e3 * w[r] * w[c]);
  };
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < rows; ++x) {
      const int b = y * rows + x;
      for (int contact = 0; contact < 2; ++contact) {
        if (x + 1 < rows) spring(b, b + 1);
        if (y + 1 < rows) spring(b, b + rows);
      }
    }
  return upper_of(entries, 6 * blocks);
}

Eigen::VectorXd right_hand_side(Eigen::Index n) { return Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin(); }

// The largest absolute row sum, ‖A‖∞.
double infinity_norm(const SparseMatrix& upper) {
  const SparseMatrix full = upper.selfadjointView<Eigen::Upper>();
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(full.rows());
  for (int c = 0; c < full.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(full, c); it; ++it) row_sums[it.row()] += std::abs(it.value());
  return row_sums.maxCoeff();
}

// κ₂ of a small matrix, from its eigenvalues.
double condition_number(const SparseMatrix& upper) {
  const Eigen::MatrixXd dense = Eigen::MatrixXd(upper).selfadjointView<Eigen::Upper>();
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues();
  return lambda.maxCoeff() / lambda.minCoeff();
}

// κ₂ of a large one, estimated: λ_max ≤ the largest absolute row sum (Gershgorin), and λ_min
// ≈ the Rayleigh quotient of 60 steps of inverse iteration (from above: κ is then estimated
// from below, which the 64 u per solve absorbs).
double estimated_condition_number(const SparseMatrix& upper) {
  const SparseMatrix full = upper.selfadjointView<Eigen::Upper>();
  const Eigen::SimplicialLLT<SparseMatrix, Eigen::Upper> factor(upper);
  Eigen::VectorXd v = Eigen::VectorXd::Ones(full.rows()).normalized();
  for (int step = 0; step < 60; ++step) v = factor.solve(v).normalized();
  const double lambda_min = v.dot(full * v);
  return infinity_norm(upper) / lambda_min;
}

double relative_difference(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
  return (x - reference).norm() / reference.norm();
}

// Each backend's answer against the first's, and each against Eigen's simplicial LLᵀ (a third,
// independent factorisation), within 2 · 64 u · κ. And each answer's own normwise backward error
// ‖b − A x̂‖∞ / (‖A‖∞ ‖x̂‖∞ + ‖b‖∞) (Rigal & Gaches 1967; Higham 2002, Thm 7.1), which κ does
// not enter, under the 64 u allowed per solve: the κ bound above is what any backward-stable
// solve may differ by, this is what each one does.
void expect_same_answers(const SparseMatrix& upper, double kappa) {
  const double tolerance = 2 * kBackwardErrorPerSolve * kappa;
  const Eigen::VectorXd b = right_hand_side(upper.rows());
  const double norm_a = infinity_norm(upper);
  const Eigen::VectorXd reference = Eigen::SimplicialLLT<SparseMatrix, Eigen::Upper>(upper).solve(b);
  std::vector<Eigen::VectorXd> answers;
  for (const Backend& backend : backends()) {
    const std::unique_ptr<SparseCholesky> solver = backend.make();
    solver->analyse(upper);
    solver->factorize(upper);
    answers.push_back(solver->solve(b));
    const Eigen::VectorXd residual = b - upper.selfadjointView<Eigen::Upper>() * answers.back();
    const double backward_error = residual.lpNorm<Eigen::Infinity>() /
                                  (norm_a * answers.back().lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
    EXPECT_LE(backward_error, kBackwardErrorPerSolve) << backend.name;
    EXPECT_LE(relative_difference(answers.back(), reference), tolerance) << backend.name << ", κ = " << kappa;
    EXPECT_LE(relative_difference(answers.back(), answers.front()), tolerance) << backend.name << ", κ = " << kappa;
  }
}

TEST(SparseCholeskyBackends, AgreeOnADarcyMatrixWithAContrastOf1e5) {
  const SparseMatrix a = darcy_matrix(152, 151);  // 22,952 unknowns: split in two halves
  ASSERT_GE(a.rows(), kSplitFrom);
  const double kappa = estimated_condition_number(a);
  EXPECT_GT(kappa, 1e5);  // the contrast is in it: the tolerance is not that of an easy matrix
  expect_same_answers(a, kappa);
}

TEST(SparseCholeskyBackends, AgreeOnAMatrixOf6x6BlocksWithStiffSprings) {
  const SparseMatrix a = block_matrix(7, 3);  // 49 blocks, 294 unknowns
  const double kappa = condition_number(a);
  EXPECT_GT(kappa, 1e3);  // the springs' contrast is in it
  expect_same_answers(a, kappa);
}

// The kept factor refactored after the values changed (the pattern the same, as between
// coupling passes: the channels' permeability ten times larger) is the fresh factorisation of
// the new matrix: the same solution to the last bit, also after the factor had been kept in
// single precision for preconditioning.
TEST(SparseCholeskyBackends, ARefactoredKeptFactorIsAFreshFactor) {
  for (const SparseMatrix& before : {darcy_matrix(152, 151), block_matrix(7, 3)}) {
    const bool darcy = before.rows() > 1000;
    const SparseMatrix after = darcy ? darcy_matrix(152, 151, 10.0) : block_matrix(7, 4);
    ASSERT_TRUE(after.isCompressed());
    const Eigen::VectorXd b = right_hand_side(before.rows());
    for (const Backend& backend : backends()) {
      const std::unique_ptr<SparseCholesky> kept = backend.make();
      kept->analyse(before);
      kept->factorize(before);
      const Eigen::VectorXd x_before = kept->solve(b);
      kept->keep_for_preconditioning();
      kept->factorize(after);
      const std::unique_ptr<SparseCholesky> fresh = backend.make();
      fresh->analyse(after);
      fresh->factorize(after);
      const Eigen::VectorXd x_kept = kept->solve(b), x_fresh = fresh->solve(b);
      EXPECT_EQ(x_kept, x_fresh) << backend.name << (darcy ? ", Darcy matrix" : ", block matrix");
      EXPECT_GT(relative_difference(x_kept, x_before), 1e-3) << "the values did change";
    }
  }
}

}  // namespace
}  // namespace hydrodda::numerics
