// Both LinearSolver implementations against a dense solve of a random SPD block matrix, and
// the factor-reuse path of the CHOLMOD solver on a nearby matrix.

#include "dda/linear_solver.hpp"

#include <gtest/gtest.h>

#include <random>

#include <Eigen/Dense>

namespace hydrodda::dda {
namespace {

// A chain of n 6×6 blocks, each coupled to the next: A = Bᵀ B + shift I is SPD.
SparseMatrix make_block_chain(int n, double scale, std::vector<std::pair<int, int>>& pairs) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  for (int b = 0; b + 1 < n; ++b) {
    Eigen::MatrixXd g(6, 12);
    for (int i = 0; i < g.size(); ++i) g.data()[i] = u(rng);
    dense.block(6 * b, 6 * b, 12, 12) += scale * g.transpose() * g;
    pairs.emplace_back(b, b + 1);
  }
  dense += Eigen::MatrixXd::Identity(6 * n, 6 * n);
  const Eigen::MatrixXd lower_dense = dense.triangularView<Eigen::Lower>();
  return lower_dense.sparseView();
}

// x = A⁻¹ b to 1e-10 relative against a dense LLᵀ, for both solvers.
TEST(LinearSolver, DirectAndIterativeMatchADenseSolve) {
  std::vector<std::pair<int, int>> pairs;
  const SparseMatrix a = make_block_chain(30, 1.0, pairs);
  const Eigen::MatrixXd dense = a.selfadjointView<Eigen::Lower>() * Eigen::MatrixXd::Identity(180, 180);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  const Eigen::VectorXd expected = dense.llt().solve(b);
  std::vector<std::unique_ptr<LinearSolver>> solvers;
  solvers.push_back(make_cholmod_solver());
  solvers.push_back(make_conjugate_gradient_solver());
  for (auto& solver : solvers) {
    solver->factor(a, 30, pairs);
    EXPECT_LT((solver->solve(b) - expected).norm(), 1e-10 * expected.norm());
  }
}

// After factor() with a perturbed matrix (1e-3 relative), the CHOLMOD solver's answer is the
// new matrix's, whether reached by CG on the old factor or by refactoring.
TEST(LinearSolver, ReusedFactorSolvesTheNewMatrix) {
  std::vector<std::pair<int, int>> pairs;
  const SparseMatrix a = make_block_chain(30, 1.0, pairs);
  const SparseMatrix a2 = make_block_chain(30, 1.001, pairs);
  const Eigen::MatrixXd dense2 = a2.selfadjointView<Eigen::Lower>() * Eigen::MatrixXd::Identity(180, 180);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  auto solver = make_cholmod_solver();
  pairs.resize(29);
  solver->factor(a, 30, pairs);
  solver->solve(b);
  solver->factor(a2, 30, pairs);
  const Eigen::VectorXd expected = dense2.llt().solve(b);
  EXPECT_LT((solver->solve(b) - expected).norm(), 1e-10 * expected.norm());
}

}  // namespace
}  // namespace hydrodda::dda
