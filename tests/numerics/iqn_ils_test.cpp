#include "numerics/iqn_ils.hpp"

#include <gtest/gtest.h>

namespace hydrodda::numerics {
namespace {

// An affine map G(x) = A x + b in n = 4 dimensions whose A has the eigenvalues −40, −3, 0.5
// and 0.2 in a basis that is not orthogonal: plain iteration x ← G(x) diverges (|−40| > 1),
// and no single relaxation ω suits both −40 (needs ω < 2/41) and 0.2. The residual
// R(x) = G(x) − x is affine, so each column of V is exactly (A − I) Δx and of W exactly A Δx;
// with n independent columns the least-squares inverse Jacobian is (A − I)⁻¹ itself and the
// next iterate is x* = (I − A)⁻¹ b (Degroote et al. 2009, §3). From a plain first step that is
// after n + 1 calls; stated: within n + 2 calls, to 1e-10 of |x*|.
struct AffineMap {
  Eigen::Matrix4d a;
  Eigen::Vector4d b{1.0, -2.0, 0.5, 3.0};
  AffineMap() {
    Eigen::Matrix4d basis;
    basis << 1.0, 0.3, 0.0, 0.2,
             0.0, 1.0, 0.5, 0.0,
             0.4, 0.0, 1.0, 0.1,
             0.0, 0.2, 0.0, 1.0;
    a = basis * Eigen::Vector4d(-40.0, -3.0, 0.5, 0.2).asDiagonal() * basis.inverse();
  }
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) const { return a * x + b; }
  Eigen::VectorXd fixed_point() const { return (Eigen::Matrix4d::Identity() - a).lu().solve(b); }
};

TEST(IqnIls, ReachesTheFixedPointOfASteepAffineMapInDimensionPlusTwoPasses) {
  const AffineMap map;
  const Eigen::VectorXd exact = map.fixed_point();
  IqnIls iqn;  // the default filter ε = 1e-2 and a plain first step
  Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
  for (int pass = 0; pass < 4 + 2; ++pass) x = iqn.next(x, map(x));
  EXPECT_LT((x - exact).norm(), 1e-10 * exact.norm());

  // Plain iteration from the same start runs away: by 40 a pass along the steep direction.
  Eigen::VectorXd plain = Eigen::VectorXd::Zero(4);
  for (int pass = 0; pass < 4 + 2; ++pass) plain = map(plain);
  EXPECT_GT((plain - exact).norm(), 1e6 * exact.norm());
}

// A first step relaxed by ω₀ (the loop's safe start on a steep map) reaches the same point, as
// fast: the columns span the same space.
TEST(IqnIls, ARelaxedFirstStepReachesTheSameFixedPoint) {
  const AffineMap map;
  const Eigen::VectorXd exact = map.fixed_point();
  IqnIls iqn({.max_columns = 20, .filter = 1e-2, .initial_relaxation = 0.02});
  Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
  const Eigen::VectorXd first = iqn.next(x, map(x));
  EXPECT_LT((first - 0.02 * map(x)).norm(), 1e-15);  // x + ω₀ (G(x) − x), x = 0
  x = first;
  for (int pass = 1; pass < 4 + 2; ++pass) x = iqn.next(x, map(x));
  EXPECT_LT((x - exact).norm(), 1e-10 * exact.norm());
}

// Residuals (1, 0), (2, 0), (3, 0), (3, 1): the second difference (1, 0) is exactly the first,
// and the filter drops the older of the two (|R_ii| = 0 < ε ‖V_i‖); the third, (0, 1), is kept.
TEST(IqnIls, TheFilterDropsAColumnParallelToANewerOne) {
  IqnIls iqn;
  const Eigen::Vector2d x = Eigen::Vector2d::Zero();
  iqn.next(x, Eigen::Vector2d(1.0, 0.0));
  EXPECT_EQ(iqn.columns(), 0);
  iqn.next(x, Eigen::Vector2d(2.0, 0.0));
  EXPECT_EQ(iqn.columns(), 1);
  const Eigen::VectorXd step = iqn.next(x, Eigen::Vector2d(3.0, 0.0));
  EXPECT_EQ(iqn.columns(), 1);
  EXPECT_TRUE(step.allFinite());
  iqn.next(x, Eigen::Vector2d(3.0, 1.0));
  EXPECT_EQ(iqn.columns(), 2);
  // The kept columns are the newest two differences, (0, 1) and (1, 0).
  EXPECT_EQ(iqn.history().v.col(0), Eigen::VectorXd(Eigen::Vector2d(0.0, 1.0)));
  EXPECT_EQ(iqn.history().v.col(1), Eigen::VectorXd(Eigen::Vector2d(1.0, 0.0)));
}

// A column nearly parallel, within ε, goes too; one just outside stays.
TEST(IqnIls, TheFilterDropsByTheRelativeLengthOfTheOrthogonalPart) {
  const auto columns_after = [](double tilt) {
    IqnIls iqn({.max_columns = 20, .filter = 1e-2, .initial_relaxation = 1.0});
    const Eigen::Vector2d x = Eigen::Vector2d::Zero();
    iqn.next(x, Eigen::Vector2d(0.0, 0.0));
    iqn.next(x, Eigen::Vector2d(1.0, tilt));  // V = (1, tilt)
    iqn.next(x, Eigen::Vector2d(2.0, tilt));  // V = (1, 0), newest
    return iqn.columns();
  };
  // The older (1, t) against the newer (1, 0): |R_22| / ‖V_2‖ = |t| / √(1 + t²).
  EXPECT_EQ(columns_after(0.5e-2), 1);
  EXPECT_EQ(columns_after(2e-2), 2);
}

TEST(IqnIls, KeepsNoMoreColumnsThanItsCap) {
  IqnIls iqn({.max_columns = 2, .filter = 0.0, .initial_relaxation = 1.0});
  const Eigen::Vector3d x = Eigen::Vector3d::Zero();
  const Eigen::Vector3d g[] = {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {2, 1, 1}};
  for (const auto& image : g) iqn.next(x, image);
  EXPECT_EQ(iqn.columns(), 2);
  EXPECT_EQ(iqn.history().v.col(0), Eigen::VectorXd(Eigen::Vector3d(1, 0, 0)));  // the newest
  EXPECT_EQ(iqn.history().v.col(1), Eigen::VectorXd(Eigen::Vector3d(0, 0, 1)));
}

// With no column the step is x + ω₀ (G(x) − x): the first call, after reset(), and after a
// change of size.
TEST(IqnIls, WithoutColumnsTakesTheRelaxedStep) {
  IqnIls iqn({.max_columns = 5, .filter = 1e-2, .initial_relaxation = 0.5});
  const Eigen::Vector2d x(1.0, 2.0), g(3.0, -2.0);
  EXPECT_EQ(iqn.next(x, g), Eigen::VectorXd(Eigen::Vector2d(2.0, 0.0)));
  iqn.next(g, Eigen::Vector2d(2.5, -0.5));
  EXPECT_EQ(iqn.columns(), 1);
  iqn.reset();
  EXPECT_EQ(iqn.columns(), 0);
  EXPECT_EQ(iqn.next(x, g), Eigen::VectorXd(Eigen::Vector2d(2.0, 0.0)));
  EXPECT_EQ(iqn.next(Eigen::Vector3d::Zero(), Eigen::Vector3d(2.0, 2.0, 2.0)),
            Eigen::VectorXd(Eigen::Vector3d(1.0, 1.0, 1.0)));
  EXPECT_EQ(iqn.columns(), 0);
}

TEST(IqnIls, RefusesSettingsOutsideTheirRange) {
  EXPECT_THROW(IqnIls({.max_columns = 0}), std::invalid_argument);
  EXPECT_THROW(IqnIls({.filter = 1.0}), std::invalid_argument);
  EXPECT_THROW(IqnIls({.initial_relaxation = 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::numerics
