#include "numerics/kept_factor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hydrodda::numerics {
namespace {

constexpr FactorReuseCosts kCosts{1e-13, 12, 2, 400, 80.0, 1.0};

TEST(FactorReusePlan, ChebyshevIterationsFollowTheConditionNumber) {
  // (c − 1)/(c + 1) per iteration: c = 1.001 cuts 1e-13 in 5; c = 10 needs 153.
  EXPECT_EQ(chebyshev_iterations(1.001, 1e-13), 5);
  EXPECT_EQ(chebyshev_iterations(10.0, 1e-13), 153);
  EXPECT_LT(chebyshev_iterations(1.1, 1e-13), chebyshev_iterations(1.3, 1e-13));
  EXPECT_LT(chebyshev_iterations(1.1, 1e-6), chebyshev_iterations(1.1, 1e-13));
}

TEST(FactorReusePlan, AnUnchangedMatrixNeedsTheFewestIterationsAndNoCorrection) {
  const std::vector<double> spreads(1000, 1.0);
  const ReusePlan plan = plan_factor_reuse(spreads, true, kCosts);
  EXPECT_TRUE(plan.corrected.empty());
  EXPECT_EQ(plan.bound, chebyshev_iterations(1.001, kCosts.tolerance));
}

TEST(FactorReusePlan, AFewPartsThatJumpedAreCorrectedExactlyWhenCorrecting) {
  std::vector<double> spreads(1000, 1.0);
  for (const int p : {3, 500, 999}) spreads[p] = 1e7;
  const ReusePlan corrected = plan_factor_reuse(spreads, true, kCosts);
  EXPECT_EQ(corrected.corrected, (std::vector<int>{3, 500, 999}));
  EXPECT_EQ(corrected.bound, chebyshev_iterations(1.001, kCosts.tolerance));
  // Not correcting: each outlying part costs its rank in iterations.
  const ReusePlan plain = plan_factor_reuse(spreads, false, kCosts);
  EXPECT_TRUE(plain.corrected.empty());
  EXPECT_EQ(plain.bound, 2 * 3 + chebyshev_iterations(1.001, kCosts.tolerance));
}

TEST(FactorReusePlan, NoCorrectionPastItsLimitOrItsCost) {
  std::vector<double> spreads(1000, 1.0);
  for (int p = 0; p < 100; ++p) spreads[p] = 1e7;  // 100 parts cost 100/80 > 1 iteration saved
  ReusePlan plan = plan_factor_reuse(spreads, true, kCosts);
  EXPECT_TRUE(plan.corrected.empty());
  EXPECT_EQ(plan.bound, 2 * 100 + chebyshev_iterations(1.001, kCosts.tolerance));
  FactorReuseCosts cheap = kCosts;
  cheap.corrected_per_iteration = 1000.0;
  EXPECT_EQ(plan_factor_reuse(spreads, true, cheap).corrected.size(), 100U);
  cheap.max_corrected_parts = 99;
  EXPECT_TRUE(plan_factor_reuse(spreads, true, cheap).corrected.empty());
}

TEST(FactorReusePlan, APartWithoutASpreadIsOutsideEveryOne) {
  std::vector<double> spreads(10, 1.0);
  spreads[4] = NAN;
  const ReusePlan plan = plan_factor_reuse(spreads, true, kCosts);
  EXPECT_EQ(plan.corrected, std::vector<int>{4});
  EXPECT_EQ(plan_factor_reuse(spreads, false, kCosts).bound, 2 + chebyshev_iterations(1.001, kCosts.tolerance));
}

// A backend that records what the preconditioner asks of it.
class RecordingFactor final : public SparseCholesky {
 public:
  void analyse(const SparseMatrix&) override {}
  void factorize(const SparseMatrix&) override {}
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return 2.0 * b; }
  void keep_for_preconditioning() override { single = true; }
  bool kept_for_preconditioning() const override { return single; }
  std::string name() const override { return "recording"; }
  std::unique_ptr<CorrectedFactor> correct(const LowRankTerm&) const override {
    ++corrections;
    if (singular) throw SingularSystem("singular");
    struct Tripled final : CorrectedFactor {
      Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return 3.0 * b; }
    };
    return std::make_unique<Tripled>();
  }
  bool single = false;
  bool singular = false;
  mutable int corrections = 0;
};

LowRankTerm term_with_weight(double weight) {
  LowRankTerm term;
  term.row = {0};
  term.value = {1.0};
  term.weight = {weight};
  term.start = {0, 1};
  return term;
}

TEST(KeptFactorPreconditioner, AppliesTheFactorAloneOrCorrected) {
  RecordingFactor factor;
  KeptFactorPreconditioner m(factor);
  const Eigen::VectorXd r = Eigen::VectorXd::Ones(3);
  Eigen::VectorXd z;
  m.use_factor_alone();
  EXPECT_TRUE(factor.single);
  m.apply(r, z);
  EXPECT_EQ(z, 2.0 * r);
  ASSERT_TRUE(m.use_corrected_factor(term_with_weight(1.0)));  // an update: made
  m.apply(r, z);
  EXPECT_EQ(z, 3.0 * r);
  m.release();
  m.apply(r, z);
  EXPECT_EQ(z, 2.0 * r);
}

TEST(KeptFactorPreconditioner, RefusesADowndateOfALowerPrecisionFactorAndASingularCorrection) {
  RecordingFactor factor;
  KeptFactorPreconditioner m(factor);
  EXPECT_TRUE(m.use_corrected_factor(term_with_weight(-1.0)));  // in double: made
  factor.single = true;
  factor.corrections = 0;
  EXPECT_FALSE(m.use_corrected_factor(term_with_weight(-1.0)));
  EXPECT_EQ(factor.corrections, 0);  // not even tried
  factor.singular = true;
  EXPECT_FALSE(m.use_corrected_factor(term_with_weight(1.0)));
  EXPECT_EQ(factor.corrections, 1);
  Eigen::VectorXd z;
  m.apply(Eigen::VectorXd::Ones(2), z);  // the factor alone after a refusal
  EXPECT_EQ(z, Eigen::VectorXd::Constant(2, 2.0));
}

}  // namespace
}  // namespace hydrodda::numerics
