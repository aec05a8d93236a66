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

// A block chain plus stiff springs w wᵀ, each over one or two blocks, as contact penalties are.
struct ChainWithSprings {
  std::vector<std::pair<int, int>> pairs;
  SparseMatrix base = make_block_chain(30, 1.0, pairs);
  std::mt19937 rng{7};
  std::uniform_real_distribution<double> u{-1.0, 1.0};

  RankOneTerm make_term(int id, int a, int b) {
    RankOneTerm t;
    t.id = {id, 0, 0, 0, 0};
    t.block_a = a;
    t.block_b = b;
    for (int r = 0; r < 6; ++r) {
      t.w_a[r] = 30.0 * u(rng);
      t.w_b[r] = 30.0 * u(rng);
    }
    return t;
  }
  Eigen::MatrixXd dense_with(const std::vector<RankOneTerm>& terms) const {
    Eigen::MatrixXd dense = base.selfadjointView<Eigen::Lower>() * Eigen::MatrixXd::Identity(180, 180);
    for (const RankOneTerm& t : terms) {
      Eigen::VectorXd w = Eigen::VectorXd::Zero(180);
      if (t.block_a >= 0) w.segment<6>(6 * t.block_a) = t.w_a;
      if (t.block_b >= 0) w.segment<6>(6 * t.block_b) = t.w_b;
      dense += w * w.transpose();
    }
    return dense;
  }
  static SparseMatrix lower_of(const Eigen::MatrixXd& dense) {
    return Eigen::MatrixXd(dense.triangularView<Eigen::Lower>()).sparseView();
  }
};

// Springs that come and go: A = B + Σ w wᵀ over the listed terms. After factor(A1, T1) and a
// solve, factor(A2, T2) with one term gone, one kept and two new: the CHOLMOD solver updates
// and downdates its factor instead of refactoring, and its answer is still A2⁻¹ b to 1e-10
// relative, the same bound as the direct solve.
TEST(LinearSolver, FactorFollowsSpringsThatComeAndGo) {
  ChainWithSprings chain;
  const RankOneTerm gone = chain.make_term(1, 3, 4), kept = chain.make_term(2, 10, 11);
  const RankOneTerm new_a = chain.make_term(3, 20, 21), new_b = chain.make_term(4, 25, -1);
  const std::vector<RankOneTerm> first{gone, kept}, second{kept, new_a, new_b};
  const Eigen::MatrixXd dense1 = chain.dense_with(first), dense2 = chain.dense_with(second);
  std::vector<std::pair<int, int>> pairs2 = chain.pairs;
  pairs2.emplace_back(25, 29);  // unused slot: the pattern may grow
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  auto solver = make_cholmod_solver();
  solver->factor(ChainWithSprings::lower_of(dense1), 30, chain.pairs, first);
  const Eigen::VectorXd x1 = dense1.llt().solve(b);
  EXPECT_LT((solver->solve(b) - x1).norm(), 1e-10 * x1.norm());
  solver->factor(ChainWithSprings::lower_of(dense2), 30, chain.pairs, second);
  const Eigen::VectorXd x2 = dense2.llt().solve(b);
  EXPECT_LT((solver->solve(b) - x2).norm(), 1e-10 * x2.norm());
  // Reached by updating, not refactoring: one factorisation, three terms changed, and (the
  // factor being exact for A2) no iteration.
  EXPECT_EQ(solver->counts().factorisations, 1);
  EXPECT_EQ(solver->counts().modified_terms, 3);
  EXPECT_EQ(solver->counts().iterations, 0);
}

// More springs changing at once than a quarter of the block count (here 10 new on 30 blocks):
// the solver factors afresh instead of updating, and the answer is still A2⁻¹ b to 1e-10.
TEST(LinearSolver, ManySpringsChangingAtOnceAreFactoredAfresh) {
  ChainWithSprings chain;
  const std::vector<RankOneTerm> first{chain.make_term(1, 0, 1)};
  std::vector<RankOneTerm> second = first;
  for (int k = 0; k < 10; ++k) second.push_back(chain.make_term(2 + k, 2 * k + 2, 2 * k + 3));
  const Eigen::MatrixXd dense1 = chain.dense_with(first), dense2 = chain.dense_with(second);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  auto solver = make_cholmod_solver();
  solver->factor(ChainWithSprings::lower_of(dense1), 30, chain.pairs, first);
  solver->solve(b);
  solver->factor(ChainWithSprings::lower_of(dense2), 30, chain.pairs, second);
  const Eigen::VectorXd x2 = dense2.llt().solve(b);
  EXPECT_LT((solver->solve(b) - x2).norm(), 1e-10 * x2.norm());
  EXPECT_EQ(solver->counts().factorisations, 2);
  EXPECT_EQ(solver->counts().modified_terms, 0);
}

}  // namespace
}  // namespace hydrodda::dda
