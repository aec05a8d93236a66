#include "numerics/woodbury.hpp"

#include <gtest/gtest.h>

namespace hydrodda::numerics {
namespace {

// (M + U S Uᵀ)⁻¹ b by the identity of woodbury.hpp, M = L Lᵀ (no permutation).
Eigen::VectorXd solve_corrected(const Eigen::LLT<Eigen::MatrixXd>& m, const Eigen::MatrixXd& u,
                                const Eigen::VectorXd& s, const Eigen::VectorXd& b, WoodburyCapacitance& c) {
  const auto l = m.matrixL();
  const Eigen::MatrixXd w = l.solve(u * s.cwiseAbs().cwiseSqrt().asDiagonal());
  const Eigen::VectorXd sigma = s.cwiseSign();
  c.factor(Eigen::MatrixXd(sigma.asDiagonal()) + w.transpose() * w);
  Eigen::VectorXd y = l.solve(b);
  y -= w * c.solve(w.transpose() * y);
  return m.matrixU().solve(y);
}

TEST(Woodbury, TheCorrectedFactorSolvesAsAFreshFactorOfTheUpdatedMatrix) {
  std::srand(11);
  const int n = 30, k = 4;
  const Eigen::MatrixXd r = Eigen::MatrixXd::Random(n, n);
  const Eigen::MatrixXd m = r * r.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd u = Eigen::MatrixXd::Random(n, k);
  Eigen::VectorXd s(k);
  s << 5.0, 0.5, -0.2, 3.0;  // updates and a downdate that leaves the sum positive definite
  const Eigen::MatrixXd updated = m + u * s.asDiagonal() * u.transpose();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  WoodburyCapacitance c;
  const Eigen::VectorXd x = solve_corrected(m.llt(), u, s, b, c);
  const Eigen::VectorXd fresh = updated.llt().solve(b);
  EXPECT_EQ(c.size(), k);
  EXPECT_FALSE(c.singular(1e-14));
  EXPECT_LT((x - fresh).norm(), 1e-12 * fresh.norm());
  EXPECT_LT((updated * x - b).norm(), 1e-12 * b.norm());
}

TEST(Woodbury, ADowndateThatRemovesAllOfADirectionIsSingular) {
  // M = I, U = e₁, S = −1: M + U S Uᵀ has a zero row, and C = −1 + 1 = 0.
  const int n = 5;
  const Eigen::MatrixXd m = Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd u = Eigen::MatrixXd::Identity(n, 1);
  WoodburyCapacitance c;
  solve_corrected(m.llt(), u, Eigen::VectorXd::Constant(1, -1.0), Eigen::VectorXd::Ones(n), c);
  EXPECT_TRUE(c.singular(1e-14));
  solve_corrected(m.llt(), u, Eigen::VectorXd::Constant(1, -0.5), Eigen::VectorXd::Ones(n), c);
  EXPECT_FALSE(c.singular(1e-14));
}

}  // namespace
}  // namespace hydrodda::numerics
