#include "numerics/anderson.hpp"

#include <gtest/gtest.h>

namespace hydrodda::numerics {
namespace {

// A linear contraction G(x) = M x + b, spectral radius 0.9: plain iteration needs about
// ln(1e-10)/ln(0.9) ≈ 220 passes to reach 1e-10. Anderson mixing with a history at least as
// deep as the dimension is, on a linear map, GMRES in disguise (Walker & Ni 2011, §4): it
// lands on x* = (I − M)⁻¹ b within n + 1 passes in exact arithmetic. Stated: within n + 2
// passes to 1e-10 of |x*|.
TEST(Anderson, ReachesTheFixedPointOfALinearMapInDimensionPlusTwoPasses) {
  Eigen::Matrix3d m;
  m << 0.9, 0.3, 0.0,
       0.0, 0.5, -0.4,
       0.1, 0.0, 0.7;
  Eigen::Matrix3d d = Eigen::Vector3d(0.9, 0.5, 0.7).asDiagonal();
  m = 0.5 * (m + d);  // keeps the spectral radius below one
  ASSERT_LT(m.eigenvalues().cwiseAbs().maxCoeff(), 1.0);
  const Eigen::Vector3d b(1.0, -2.0, 0.5);
  const Eigen::Vector3d exact = (Eigen::Matrix3d::Identity() - m).lu().solve(b);
  const auto map = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return m * x + b; };

  AndersonAccelerator mixing(3);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  for (int pass = 0; pass < 5; ++pass) x = mixing.next(x, map(x));
  EXPECT_LT((x - exact).norm(), 1e-10 * exact.norm());

  // Plain iteration from the same start is nowhere near after as many passes.
  Eigen::VectorXd plain = Eigen::VectorXd::Zero(3);
  for (int pass = 0; pass < 5; ++pass) plain = map(plain);
  EXPECT_GT((plain - exact).norm(), 1e-2 * exact.norm());
}

// With no history the step is the plain one, x ← G(x): the first call, and the first after
// reset().
TEST(Anderson, WithoutHistoryTakesThePlainStep) {
  AndersonAccelerator mixing;
  const Eigen::Vector2d x(1.0, 2.0), g(3.0, -1.0);
  EXPECT_EQ(mixing.next(x, g), Eigen::VectorXd(g));
  EXPECT_NE(mixing.next(g, Eigen::Vector2d(2.5, -0.5)), Eigen::VectorXd(Eigen::Vector2d(2.5, -0.5)));
  mixing.reset();
  EXPECT_EQ(mixing.next(x, g), Eigen::VectorXd(g));
  // A change of size starts again too.
  const Eigen::Vector3d g3(1.0, 1.0, 1.0);
  EXPECT_EQ(mixing.next(Eigen::Vector3d::Zero(), g3), Eigen::VectorXd(g3));
}

}  // namespace
}  // namespace hydrodda::numerics
