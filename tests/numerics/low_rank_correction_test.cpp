// SparseCholesky::correct on CHOLMOD's supernodal factor: (A + U S Uᵀ)⁻¹ b applied from the
// factor of A (Sherman–Morrison–Woodbury, numerics/supernodal_correction.cpp) against a fresh
// factorisation of A + U S Uᵀ. Both are exact up to round-off: the matrices here have
// condition numbers near 1e3–1e4, so the two answers agree to 1e-11 relative.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "numerics/cholmod_solver.hpp"

namespace hydrodda::numerics {
namespace {

constexpr double kAgreement = 1e-11;  // relative, ‖x_corrected − x_fresh‖∞ / ‖x_fresh‖∞

// The 5-point Laplacian on an n × n grid plus a small shift (SPD), upper triangle.
Eigen::MatrixXd grid_laplacian(int n) {
  const int size = n * n;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(size, size);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int p = j * n + i;
      a(p, p) = 4.01;
      if (i + 1 < n) a(p, p + 1) = a(p + 1, p) = -1.0;
      if (j + 1 < n) a(p, p + n) = a(p + n, p) = -1.0;
    }
  return a;
}

SparseMatrix upper_sparse(const Eigen::MatrixXd& dense) {
  const SparseMatrix full = dense.sparseView();
  return full.triangularView<Eigen::Upper>();
}

// Columns as an element change makes them: a few neighbouring rows each, weights of both signs
// (a downdate never more than a quarter of what the column's rows hold, so A + U S Uᵀ stays SPD).
LowRankTerm random_term(int size, int columns, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> row(0, size - 4);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  LowRankTerm term;
  for (int j = 0; j < columns; ++j) {
    const int first = row(random);
    for (int r : {first, first + 1, first + 3}) {
      term.row.push_back(r);
      term.value.push_back(value(random));
    }
    term.start.push_back(static_cast<int>(term.row.size()));
    term.weight.push_back(j % 3 == 2 ? -0.05 : 50.0 * (1.0 + value(random)));
  }
  return term;
}

Eigen::MatrixXd add_term(Eigen::MatrixXd a, const LowRankTerm& term) {
  for (int j = 0; j < term.columns(); ++j)
    for (int p = term.start[j]; p < term.start[j + 1]; ++p)
      for (int q = term.start[j]; q < term.start[j + 1]; ++q)
        a(term.row[p], term.row[q]) += term.weight[j] * term.value[p] * term.value[q];
  return a;
}

double relative_difference(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
  return (x - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

TEST(LowRankCorrection, SolvesTheCorrectedMatrixAsAFreshFactorDoes) {
  const Eigen::MatrixXd a = grid_laplacian(40);  // 1,600 unknowns, many supernodes
  const LowRankTerm term = random_term(static_cast<int>(a.rows()), 60, 7);
  const Eigen::MatrixXd corrected = add_term(a, term);
  ASSERT_EQ(Eigen::LLT<Eigen::MatrixXd>(corrected).info(), Eigen::Success);  // still SPD

  auto kept = make_cholmod_solver();
  kept->analyse(upper_sparse(a));
  kept->factorize(upper_sparse(a));
  auto fresh = make_cholmod_solver();
  fresh->analyse(upper_sparse(corrected));
  fresh->factorize(upper_sparse(corrected));

  const std::unique_ptr<CorrectedFactor> update = kept->correct(term);
  ASSERT_NE(update, nullptr);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd b(a.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = value(random);
    const Eigen::VectorXd x = update->solve(b);
    EXPECT_LE(relative_difference(x, fresh->solve(b)), kAgreement);
    // And it is the corrected matrix's solution: A' x = b to round-off.
    EXPECT_LE((corrected * x - b).lpNorm<Eigen::Infinity>(), 1e-11 * b.lpNorm<Eigen::Infinity>());
  }
}

// With the factor kept for preconditioning (in single precision: M̃ = Pᵀ L̃ L̃ᵀ P, L̃ the factor
// rounded to float), the correction is exact for M̃ + U S Uᵀ: x = M̃⁻¹ (b − U S Uᵀ x) to
// round-off, M̃⁻¹ applied by precondition(). solve() is refused meanwhile.
TEST(LowRankCorrection, CorrectsTheFactorKeptForPreconditioning) {
  const Eigen::MatrixXd a = grid_laplacian(40);
  const LowRankTerm term = random_term(static_cast<int>(a.rows()), 60, 7);
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(a.rows(), term.columns());
  for (int j = 0; j < term.columns(); ++j)
    for (int p = term.start[j]; p < term.start[j + 1]; ++p) u(term.row[p], j) = term.value[p];
  const Eigen::VectorXd s = Eigen::Map<const Eigen::VectorXd>(term.weight.data(), term.columns());

  auto kept = make_cholmod_solver();
  kept->analyse(upper_sparse(a));
  kept->factorize(upper_sparse(a));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0).array().sin();
  const Eigen::VectorXd x_exact = kept->solve(b);
  kept->keep_for_preconditioning();
  EXPECT_THROW(kept->solve(b), std::logic_error);
  EXPECT_GT(relative_difference(kept->precondition(b), x_exact), 0.0);  // M̃ is not A

  const std::unique_ptr<CorrectedFactor> update = kept->correct(term);
  ASSERT_NE(update, nullptr);
  const Eigen::VectorXd x = update->solve(b);
  const Eigen::VectorXd recovered = kept->precondition(b - u * s.asDiagonal() * (u.transpose() * x));
  EXPECT_LE(relative_difference(recovered, x), kAgreement);

  kept->factorize(upper_sparse(a));  // double again: the exact solve as before
  EXPECT_EQ(relative_difference(kept->solve(b), x_exact), 0.0);
}

TEST(LowRankCorrection, AnEmptyTermLeavesTheFactorsSolve) {
  const Eigen::MatrixXd a = grid_laplacian(20);
  auto solver = make_cholmod_solver();
  solver->analyse(upper_sparse(a));
  solver->factorize(upper_sparse(a));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  const std::unique_ptr<CorrectedFactor> update = solver->correct(LowRankTerm{});
  EXPECT_LE(relative_difference(update->solve(b), solver->solve(b)), 1e-14);
}

// A downdate that takes away all a row holds makes A + U S Uᵀ singular: the correction says
// so rather than solve with it.
TEST(LowRankCorrection, ASingularCorrectedMatrixIsRefused) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 3);
  a.diagonal() << 2.0, 3.0, 4.0;
  auto solver = make_cholmod_solver();
  solver->analyse(upper_sparse(a));
  solver->factorize(upper_sparse(a));
  LowRankTerm term;
  term.row = {1};
  term.value = {1.0};
  term.start = {0, 1};
  term.weight = {-3.0};  // A(1, 1) − 3 = 0
  EXPECT_THROW(solver->correct(term), SingularSystem);
}

TEST(LowRankCorrection, NeedsAFactor) {
  auto solver = make_cholmod_solver();
  EXPECT_THROW(solver->correct(LowRankTerm{}), std::logic_error);
}

}  // namespace
}  // namespace hydrodda::numerics
