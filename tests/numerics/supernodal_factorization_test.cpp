// SupernodalFactorization: the factor of CHOLMOD's own analysis, filled on two threads, against
// CHOLMOD's numeric factorisation of the same analysis (cholmod_factorize); its solves against
// CHOLMOD's. Both are backward-stable Cholesky factorisations that add the same products in
// different orders: their entries agree to round-off, 1e-13 of the largest (the matrices here
// have conductances spread over two decades, condition numbers near 1e5).

#include "numerics/supernodal_factorization.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/CholmodSupport>

#include "numerics/nested_dissection.hpp"

namespace hydrodda::numerics {
namespace {

constexpr double kEntryAgreement = 1e-13;  // max |L_ours − L_cholmod| / max |L_cholmod|
constexpr double kSolveAgreement = 1e-11;  // ‖x_ours − x_cholmod‖∞ / ‖x_cholmod‖∞

// A flow matrix's shape: the P1 graph of an nx × ny grid of squares cut into triangles, each
// edge a conductance between 0.1 and 10, plus a small shift (SPD); upper triangle.
SparseMatrix flow_like_matrix(int nx, int ny, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> exponent(-1.0, 1.0);
  const int n = nx * ny;
  std::vector<double> diagonal(n, 1e-3);
  std::vector<Eigen::Triplet<double>> entries;
  const auto couple = [&](int a, int b) {
    const double k = std::pow(10.0, exponent(random));
    entries.emplace_back(std::min(a, b), std::max(a, b), -k);
    diagonal[a] += k;
    diagonal[b] += k;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int p = j * nx + i;
      if (i + 1 < nx) couple(p, p + 1);
      if (j + 1 < ny) couple(p, p + nx);
      if (i + 1 < nx && j + 1 < ny) couple(p, p + nx + 1);
    }
  for (int p = 0; p < n; ++p) entries.emplace_back(p, p, diagonal[p]);
  SparseMatrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  a.makeCompressed();
  return a;
}

// Two analyses of `a` in the nested-dissection order: one for CHOLMOD to factor, one for ours.
class Analyses {
 public:
  explicit Analyses(const SparseMatrix& a) : upper_(a), order_(order_by_nested_dissection(a)) {
    cholmod_start(&common_);
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_GIVEN;
    common_.supernodal = CHOLMOD_SUPERNODAL;
    cholmod_sparse view = Eigen::viewAsCholmod(std::as_const(upper_).selfadjointView<Eigen::Upper>());
    theirs_ = cholmod_analyze_p(&view, order_.order.data(), nullptr, 0, &common_);
    ours_ = cholmod_analyze_p(&view, order_.order.data(), nullptr, 0, &common_);
  }
  ~Analyses() {
    cholmod_free_factor(&theirs_, &common_);
    cholmod_free_factor(&ours_, &common_);
    cholmod_finish(&common_);
  }
  Analyses(const Analyses&) = delete;
  Analyses& operator=(const Analyses&) = delete;

  cholmod_factor* cholmod_factor_of(const SparseMatrix& values) {
    cholmod_sparse view = Eigen::viewAsCholmod(values.selfadjointView<Eigen::Upper>());
    EXPECT_TRUE(cholmod_factorize(&view, theirs_, &common_));
    EXPECT_EQ(theirs_->minor, theirs_->n);
    return theirs_;
  }
  SupernodalFactorization ours() { return SupernodalFactorization(ours_, &common_, upper_, order_.parts()); }
  cholmod_factor* ours_factor() const { return ours_; }
  cholmod_common* common() { return &common_; }

 private:
  SparseMatrix upper_;
  FillOrder order_;
  cholmod_common common_{};
  cholmod_factor* theirs_ = nullptr;
  cholmod_factor* ours_ = nullptr;
};

Eigen::VectorXd cholmod_solution(Analyses& analyses, const SparseMatrix& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd copy = b;
  cholmod_dense rhs = Eigen::viewAsCholmod(copy);
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, analyses.cholmod_factor_of(a), &rhs, analyses.common());
  Eigen::VectorXd out = Eigen::Map<Eigen::VectorXd>(static_cast<double*>(x->x), a.rows());
  cholmod_free_dense(&x, analyses.common());
  return out;
}

std::vector<double> values_of(const cholmod_factor* f) {
  const double* x = static_cast<const double*>(f->x);
  return std::vector<double>(x, x + f->xsize);
}

TEST(SupernodalFactorization, FactorsASplitMatrixAsCholmodDoes) {
  const SparseMatrix a = flow_like_matrix(170, 150, 1);  // 25,500 unknowns: split in two
  ASSERT_GE(a.rows(), kSplitFrom);
  Analyses analyses(a);
  SupernodalFactorization ours = analyses.ours();
  EXPECT_GT(ours.supernodes_in(0), 100u);  // each half's work on its own thread
  EXPECT_GT(ours.supernodes_in(1), 100u);
  EXPECT_GE(ours.supernodes_in(2), 1u);

  ours.factorize(a, /*two_threads=*/true);
  const std::vector<double> two = values_of(analyses.ours_factor());
  ours.factorize(a, /*two_threads=*/false);
  const std::vector<double> one = values_of(analyses.ours_factor());
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)), 0);  // bit for bit

  const std::vector<double> theirs = values_of(analyses.cholmod_factor_of(a));
  ASSERT_EQ(theirs.size(), two.size());
  double largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < theirs.size(); ++k) {
    largest = std::max(largest, std::abs(theirs[k]));
    difference = std::max(difference, std::abs(theirs[k] - two[k]));
  }
  EXPECT_LE(difference, kEntryAgreement * largest);

  // Its solve (P, L, Lᵀ, Pᵀ on the halves' threads) against CHOLMOD's on CHOLMOD's factor.
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 3.0).array().sin();
  const Eigen::VectorXd x_two = ours.solve(b, true), x_one = ours.solve(b, false);
  EXPECT_EQ(std::memcmp(x_one.data(), x_two.data(), x_one.size() * sizeof(double)), 0);
  const Eigen::VectorXd expected = cholmod_solution(analyses, a, b);
  EXPECT_LE((x_two - expected).lpNorm<Eigen::Infinity>(), kSolveAgreement * expected.lpNorm<Eigen::Infinity>());
}

TEST(SupernodalFactorization, FactorsAMatrixOrderedWholeOnOneThread) {
  const SparseMatrix a = flow_like_matrix(60, 50, 2);  // below kSplitFrom: no halves
  Analyses analyses(a);
  SupernodalFactorization ours = analyses.ours();
  EXPECT_EQ(ours.supernodes_in(0) + ours.supernodes_in(1), 0u);
  ours.factorize(a, true);
  const std::vector<double> mine = values_of(analyses.ours_factor());
  const std::vector<double> theirs = values_of(analyses.cholmod_factor_of(a));
  double largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < theirs.size(); ++k) {
    largest = std::max(largest, std::abs(theirs[k]));
    difference = std::max(difference, std::abs(theirs[k] - mine[k]));
  }
  EXPECT_LE(difference, kEntryAgreement * largest);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), 2.0, -1.0);
  const Eigen::VectorXd x = ours.solve(b, true), expected = cholmod_solution(analyses, a, b);
  EXPECT_LE((x - expected).lpNorm<Eigen::Infinity>(), kSolveAgreement * expected.lpNorm<Eigen::Infinity>());
}

// Kept in single precision, the factor's values are rounded to float and the double ones let
// go; its solve is then the exact solve with the rounded factor L̃: CHOLMOD's solve on a copy of
// the factor whose values are L's rounded to float and back, to the same 1e-11 (the two add
// the same products in different orders). The next factorisation brings the double values
// back, bit for bit as before.
TEST(SupernodalFactorization, KeptInSinglePrecisionSolvesWithTheRoundedFactor) {
  const SparseMatrix a = flow_like_matrix(170, 150, 4);
  Analyses analyses(a);
  SupernodalFactorization ours = analyses.ours();
  ours.factorize(a, true);
  const std::vector<double> exact = values_of(analyses.ours_factor());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -2.0, 1.0).array().cos();
  const Eigen::VectorXd x_exact = ours.solve(b, true);

  cholmod_factor* rounded = analyses.cholmod_factor_of(a);
  ASSERT_EQ(rounded->xsize, exact.size());
  double* values = static_cast<double*>(rounded->x);
  for (std::size_t k = 0; k < exact.size(); ++k) values[k] = static_cast<double>(static_cast<float>(exact[k]));
  Eigen::VectorXd copy = b;
  cholmod_dense rhs = Eigen::viewAsCholmod(copy);
  cholmod_dense* solved = cholmod_solve(CHOLMOD_A, rounded, &rhs, analyses.common());
  const Eigen::VectorXd expected = Eigen::Map<Eigen::VectorXd>(static_cast<double*>(solved->x), a.rows());
  cholmod_free_dense(&solved, analyses.common());

  EXPECT_FALSE(ours.in_single_precision());
  ours.keep_in_single_precision();
  ASSERT_TRUE(ours.in_single_precision());
  EXPECT_EQ(analyses.ours_factor()->x, nullptr);  // the double values are gone
  EXPECT_EQ(analyses.ours_factor()->xtype, CHOLMOD_PATTERN);
  const Eigen::VectorXd x_two = ours.solve(b, true), x_one = ours.solve(b, false);
  EXPECT_EQ(std::memcmp(x_one.data(), x_two.data(), x_one.size() * sizeof(double)), 0);
  EXPECT_LE((x_two - expected).lpNorm<Eigen::Infinity>(), kSolveAgreement * expected.lpNorm<Eigen::Infinity>());
  EXPECT_GT((x_two - x_exact).lpNorm<Eigen::Infinity>(), 0.0);  // the rounded factor is the one in use

  ours.factorize(a, true);
  EXPECT_FALSE(ours.in_single_precision());
  const std::vector<double> again = values_of(analyses.ours_factor());
  ASSERT_EQ(again.size(), exact.size());
  EXPECT_EQ(std::memcmp(again.data(), exact.data(), exact.size() * sizeof(double)), 0);
  const Eigen::VectorXd x_again = ours.solve(b, true);
  EXPECT_EQ(std::memcmp(x_again.data(), x_exact.data(), x_exact.size() * sizeof(double)), 0);
}

// A negative pivot, in either half or in the separator, is refused as CHOLMOD refuses it.
TEST(SupernodalFactorization, RefusesAMatrixThatIsNotPositiveDefinite) {
  const SparseMatrix a = flow_like_matrix(170, 150, 3);
  const FillOrder order = order_by_nested_dissection(a);
  const std::vector<int> part = order.parts();
  ASSERT_FALSE(part.empty());
  for (int where : {0, 1, 2}) {
    int unknown = 0;
    while (part[unknown] != where) ++unknown;
    SparseMatrix broken = a;
    broken.coeffRef(unknown, unknown) = -1.0;
    Analyses analyses(broken);
    SupernodalFactorization ours = analyses.ours();
    EXPECT_THROW(ours.factorize(broken, true), SingularSystem) << "part " << where;
  }
}

}  // namespace
}  // namespace hydrodda::numerics
