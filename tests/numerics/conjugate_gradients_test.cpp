#include "numerics/conjugate_gradients.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace hydrodda::numerics {
namespace {

// A symmetric positive definite matrix of condition about 1e4: Qᵀ D Q with D spread over
// [1, 1e4] and Q orthogonal (from a fixed seed's QR).
Eigen::MatrixXd spd_matrix(int n) {
  std::srand(7);
  const Eigen::MatrixXd q = Eigen::MatrixXd::Random(n, n).householderQr().householderQ();
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = std::pow(1e4, static_cast<double>(i) / (n - 1));
  return q.transpose() * d.asDiagonal() * q;
}

VectorOperator product_with(const Eigen::MatrixXd& a) {
  return [&a](const Eigen::VectorXd& x, Eigen::VectorXd& y) { y = a * x; };
}

// M = diag(A): Jacobi.
VectorOperator jacobi_of(const Eigen::MatrixXd& a) {
  return [&a](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = r.cwiseQuotient(a.diagonal()); };
}

TEST(ConjugateGradients, SolvesAnSpdSystemToItsRelativeTolerance) {
  const int n = 40;
  const Eigen::MatrixXd a = spd_matrix(n);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (const double tolerance : {1e-6, 1e-8, 1e-10}) {
    Eigen::VectorXd x;
    long iterations = 0;
    const int taken = solve_by_conjugate_gradients(product_with(a), jacobi_of(a), b, {}, tolerance, 500, x, iterations);
    ASSERT_GT(taken, 0) << tolerance;
    EXPECT_EQ(iterations, taken);
    EXPECT_LE((b - a * x).norm(), tolerance * b.norm()) << tolerance;
    // Not far past it either: the residual just before was still above the tolerance.
    EXPECT_GT((b - a * x).norm(), 1e-4 * tolerance * b.norm()) << tolerance;
  }
}

// In exact arithmetic CG ends within n iterations; with M = A⁻¹ exactly, in one.
TEST(ConjugateGradients, TheExactInverseAsPreconditionerSolvesInOneIteration) {
  const int n = 12;
  const Eigen::MatrixXd a = spd_matrix(n);
  const Eigen::LLT<Eigen::MatrixXd> llt(a);
  const VectorOperator exact = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = llt.solve(r); };
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  Eigen::VectorXd x;
  long iterations = 0;
  EXPECT_EQ(solve_by_conjugate_gradients(product_with(a), exact, b, {}, 1e-12, 10, x, iterations), 1);
  EXPECT_LE((b - a * x).norm(), 1e-12 * b.norm());
}

TEST(ConjugateGradients, AGoodGuessIsTakenAndAnExactOneNeedsNoIteration) {
  const int n = 20;
  const Eigen::MatrixXd a = spd_matrix(n);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 3.0);
  const Eigen::VectorXd exact = a.llt().solve(b);
  Eigen::VectorXd x;
  long iterations = 0;
  EXPECT_EQ(solve_by_conjugate_gradients(product_with(a), jacobi_of(a), b, exact, 1e-8, 100, x, iterations), 0);
  EXPECT_LT((x - exact).norm(), 1e-15 * exact.norm() * n);  // scaled by 1/‖b‖ and back
  // A guess worse than zero is dropped: the answer is the one from zero.
  Eigen::VectorXd from_zero, from_bad;
  ASSERT_GT(solve_by_conjugate_gradients(product_with(a), jacobi_of(a), b, {}, 1e-10, 500, from_zero, iterations), 0);
  ASSERT_GT(solve_by_conjugate_gradients(product_with(a), jacobi_of(a), b, -1e6 * exact, 1e-10, 500, from_bad, iterations), 0);
  EXPECT_EQ(from_zero, from_bad);
}

TEST(ConjugateGradients, GivesUpPastItsIterationsOrWhenTheRuleSaysSo) {
  const int n = 40;
  const Eigen::MatrixXd a = spd_matrix(n);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  Eigen::VectorXd x;
  long iterations = 0;
  EXPECT_EQ(solve_by_conjugate_gradients(product_with(a), jacobi_of(a), b, {}, 1e-14, 3, x, iterations), -1);
  EXPECT_EQ(iterations, 3);

  // A rule that converges on z's size, gives up at the second iteration.
  int asked = 0;
  const CgStoppingRule rule{{}, [&](int it, const Eigen::VectorXd&, const Eigen::VectorXd&) {
                              ++asked;
                              return it == 2 ? CgVerdict::give_up : CgVerdict::go_on;
                            }};
  x = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd r = b;
  iterations = 0;
  EXPECT_EQ(run_preconditioned_cg(product_with(a), jacobi_of(a), rule, 50, x, r, iterations), -1);
  EXPECT_EQ(asked, 3);  // at the start, then after iterations 1 and 2
  EXPECT_EQ(iterations, 2);
  // r is kept the residual of x.
  EXPECT_LT((b - a * x - r).norm(), 1e-10 * b.norm());
}

TEST(ConjugateGradients, BreaksDownOnAnIndefiniteMatrix) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Identity(3, 3);
  a(2, 2) = -1.0;
  const Eigen::VectorXd b = Eigen::Vector3d(0.0, 0.0, 1.0);
  const VectorOperator identity = [](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = r; };
  Eigen::VectorXd x;
  long iterations = 0;
  EXPECT_EQ(solve_by_conjugate_gradients(product_with(a), identity, b, {}, 1e-12, 10, x, iterations), -1);
}

}  // namespace
}  // namespace hydrodda::numerics
