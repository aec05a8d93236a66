// The LinearSolver implementations against a dense solve of a random SPD block matrix, and
// the factor-reuse paths of the kept-factor solvers (block Cholesky, CHOLMOD) on nearby
// matrices and springs that come and go.

#include "dda/linear_solver.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <iterator>
#include <random>
#include <set>

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
  solvers.push_back(make_block_factor_solver());
  solvers.push_back(make_cholmod_solver());
  solvers.push_back(make_conjugate_gradient_solver());
  for (auto& solver : solvers) {
    solver->factor(block_form(a, 30));
    EXPECT_LT((solver->solve(b) - expected).norm(), 1e-10 * expected.norm());
  }
}

// estimate(b, 1e-2) leaves ‖b − A x‖ ≤ 1e-2 ‖b‖ (the residual is what CG's stopping test
// bounds; checked against the dense matrix), and leaves solve() as it was: a solve after an
// estimate gives the bits a solve without one gives (the estimate starts from zero, keeps no
// starting guess, and does not decide when to factor afresh). For every solver, on matrices
// the kept factors have drifted from a little (1e-3) and far (the coupling thirtyfold). Far
// off, the estimate takes more iterations than a solve may before the factor is made again,
// and CG is allowed enough iterations (200) that the solves themselves still converge on the
// kept factor: an estimate that applied the rule would have the next solve factor afresh.
TEST(LinearSolver, EstimateMeetsItsResidualAndLeavesSolveAlone) {
  std::vector<std::pair<int, int>> pairs;
  const SparseMatrix a = make_block_chain(30, 1.0, pairs);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  const Eigen::VectorXd change = 1e-3 * Eigen::VectorXd::LinSpaced(180, 1.0, -0.5);
  using Make = std::unique_ptr<LinearSolver> (*)();
  for (const double drift : {1.001, 30.0}) {
    const SparseMatrix drifted = make_block_chain(30, drift, pairs);
    const Eigen::MatrixXd dense =
        drifted.selfadjointView<Eigen::Lower>() * Eigen::MatrixXd::Identity(180, 180);
    for (Make make : {Make{[] { return make_block_factor_solver(1e-12, 200); }},
                      Make{[] { return make_cholmod_solver(1e-12, 200); }},
                      Make{[] { return make_conjugate_gradient_solver(); }}}) {
      auto with = make();
      auto without = make();
      for (auto* solver : {with.get(), without.get()}) {
        solver->factor(block_form(a, 30));
        solver->solve(b);
        solver->factor(block_form(drifted, 30));
      }
      const long before = with->counts().iterations;
      const Eigen::VectorXd x = with->estimate(change, 1e-2);
      // Far off, more than the six iterations after which a kept-factor solver's solve has
      // the factor made again.
      if (drift > 2.0) {
        EXPECT_GT(with->counts().iterations - before, 6);
      }
      EXPECT_LE((change - dense * x).norm(), 1e-2 * change.norm());
      EXPECT_EQ(with->counts().estimates, 1);
      const Eigen::VectorXd after = with->solve(b + change);
      const Eigen::VectorXd alone = without->solve(b + change);
      EXPECT_EQ(after, alone);
    }
  }
}

// The solvers that keep a factorisation from call to call.
struct KeptFactorSolver {
  const char* name;
  std::unique_ptr<LinearSolver> (*make)();
};
std::unique_ptr<LinearSolver> make_block() { return make_block_factor_solver(); }
std::unique_ptr<LinearSolver> make_cholmod() { return make_cholmod_solver(); }

class KeptFactor : public ::testing::TestWithParam<KeptFactorSolver> {};

INSTANTIATE_TEST_SUITE_P(LinearSolver, KeptFactor,
                         ::testing::Values(KeptFactorSolver{"block", make_block},
                                           KeptFactorSolver{"cholmod", make_cholmod}),
                         [](const auto& info) { return std::string(info.param.name); });

// After factor() with a perturbed matrix (1e-3 relative), the answer is the new matrix's,
// whether reached by CG on the old factor or by refactoring.
TEST_P(KeptFactor, ReusedFactorSolvesTheNewMatrix) {
  std::vector<std::pair<int, int>> pairs;
  const SparseMatrix a = make_block_chain(30, 1.0, pairs);
  const SparseMatrix a2 = make_block_chain(30, 1.001, pairs);
  const Eigen::MatrixXd dense2 = a2.selfadjointView<Eigen::Lower>() * Eigen::MatrixXd::Identity(180, 180);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  auto solver = GetParam().make();
  solver->factor(block_form(a, 30));
  solver->solve(b);
  solver->factor(block_form(a2, 30));
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
  Eigen::MatrixXd dense_with(const RankOneTerms& terms) const {
    Eigen::MatrixXd dense = base.selfadjointView<Eigen::Lower>() * Eigen::MatrixXd::Identity(180, 180);
    for (const RankOneTerm& t : terms) {
      Eigen::VectorXd w = Eigen::VectorXd::Zero(180);
      if (t.block_a >= 0) w.segment<6>(6 * t.block_a) += t.w_a;
      if (t.block_b >= 0) w.segment<6>(6 * t.block_b) += t.w_b;
      dense += w * w.transpose();
    }
    return dense;
  }
  BlockMatrix base_blocks() const { return block_form(base, 30); }
};

// The springs assembled into blocks, and multiplied by without assembling, give exactly the
// dense B + Σ w wᵀ (to round-off, 1e-12 relative): springs over two blocks in either order,
// over one block, and over the same block twice (its two vectors summed).
TEST(LinearSolver, SpringsAddUpToTheDenseMatrix) {
  ChainWithSprings chain;
  RankOneTerms springs{chain.make_term(1, 3, 4), chain.make_term(2, 12, 7), chain.make_term(3, 20, -1),
                       chain.make_term(4, -1, 25), chain.make_term(5, 9, 9)};
  const Eigen::MatrixXd dense = chain.dense_with(springs);
  const BlockMatrix assembled = add_springs(chain.base_blocks(), springs);
  const Eigen::MatrixXd from_blocks =
      assembled.lower_triangle().selfadjointView<Eigen::Lower>() * Eigen::MatrixXd::Identity(180, 180);
  EXPECT_LT((from_blocks - dense).norm(), 1e-12 * dense.norm());
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(180, -3.0, 1.0);
  Eigen::VectorXd y;
  multiply_with_springs(chain.base_blocks(), springs, x, y);
  EXPECT_LT((y - dense * x).norm(), 1e-12 * (dense * x).norm());
}

// The product split by block rows between two threads (SpringMatrixProduct) is the one-thread
// product bit for bit: each row sums the same terms in the same order. 12,000 springs (past
// the split's threshold of 10,000) between random blocks, across the middle of the chain,
// within one block, at one end only, the same block at both ends.
TEST(LinearSolver, SplitSpringProductIsTheSerialOneBitForBit) {
  ChainWithSprings chain;
  std::uniform_int_distribution<int> block(-1, 29);
  RankOneTerms springs;
  for (int i = 0; i < 12000; ++i) {
    int a = block(chain.rng), b = block(chain.rng);
    if (a < 0 && b < 0) a = 14;
    springs.push_back(chain.make_term(i, a, b));
  }
  springs.push_back(chain.make_term(12000, 14, 15));  // across the split of 30 blocks at 15
  springs.push_back(chain.make_term(12001, 15, 15));
  const BlockMatrix base = chain.base_blocks();
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(180, -3.0, 1.0);
  Eigen::VectorXd serial;
  multiply_with_springs(base, springs, x, serial);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  SpringMatrixProduct product;
  product.reset(base, springs);
  EXPECT_TRUE(product.splits());
  Eigen::VectorXd split = Eigen::VectorXd::Constant(180, 1e300);  // every entry must be written
  product.multiply(x, split);
  omp_set_num_threads(3);  // three shares of the rows: a spring may cross two of them
  SpringMatrixProduct in_three;
  in_three.reset(base, springs);
  Eigen::VectorXd split_three = Eigen::VectorXd::Constant(180, 1e300);
  in_three.multiply(x, split_three);
  omp_set_num_threads(threads);
  ASSERT_EQ(split.size(), serial.size());
  for (Eigen::Index i = 0; i < serial.size(); ++i) EXPECT_EQ(split[i], serial[i]) << "entry " << i;
  ASSERT_EQ(split_three.size(), serial.size());
  for (Eigen::Index i = 0; i < serial.size(); ++i) EXPECT_EQ(split_three[i], serial[i]) << "entry " << i;
  EXPECT_LT((serial - chain.dense_with(springs) * x).norm(), 1e-12 * serial.norm());
}

// Springs that come and go: A = B + Σ w wᵀ over the listed terms. After factor(B, T1) and a
// solve, factor(B, T2) with one term gone, one kept and two new: the solver follows the
// three changed springs (CHOLMOD updates and downdates its factor; the block solver corrects
// its preconditioner by Sherman–Morrison–Woodbury) instead of refactoring, and its answer is still A2⁻¹ b to 1e-10
// relative, the same bound as the direct solve.
TEST_P(KeptFactor, FactorFollowsSpringsThatComeAndGo) {
  ChainWithSprings chain;
  const RankOneTerm gone = chain.make_term(1, 3, 4), kept = chain.make_term(2, 10, 11);
  const RankOneTerm new_a = chain.make_term(3, 20, 21), new_b = chain.make_term(4, 25, -1);
  const RankOneTerms first{gone, kept}, second{kept, new_a, new_b};
  const Eigen::MatrixXd dense1 = chain.dense_with(first), dense2 = chain.dense_with(second);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  auto solver = GetParam().make();
  solver->factor(chain.base_blocks(), first);
  const Eigen::VectorXd x1 = dense1.llt().solve(b);
  EXPECT_LT((solver->solve(b) - x1).norm(), 1e-10 * x1.norm());
  const long iterations_before = solver->counts().iterations;
  solver->factor(chain.base_blocks(), second);
  const Eigen::VectorXd x2 = dense2.llt().solve(b);
  EXPECT_LT((solver->solve(b) - x2).norm(), 1e-10 * x2.norm());
  // Reached by following, not refactoring: one factorisation and three terms changed. The
  // followed factor is exact for A2, so CG needs one iteration in exact arithmetic, and one
  // more at most for the round-off of the downdate (w wᵀ taken back out of the factor that
  // holds it); an uncorrected factor would need up to four (three rank-one changes).
  EXPECT_EQ(solver->counts().factorisations, 1);
  EXPECT_EQ(solver->counts().modified_terms, 3);
  EXPECT_LE(solver->counts().iterations - iterations_before, 2);
}

// The springs passed by reference (factor_borrowing) give the bits that copies (factor) give,
// with the caller's lists written over in place between calls as a DDA step does: the solver
// reads the current contents, and follows the change from the first set to the second.
TEST_P(KeptFactor, BorrowedSpringsGiveTheAnswersOfCopiedOnes) {
  ChainWithSprings chain;
  const RankOneTerms first{chain.make_term(1, 3, 4), chain.make_term(2, 10, 11)};
  const RankOneTerms second{chain.make_term(2, 10, 11), chain.make_term(3, 20, 21), chain.make_term(4, 25, -1)};
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  auto copying = GetParam().make();
  auto borrowing = GetParam().make();
  BlockMatrix base = chain.base_blocks();
  RankOneTerms springs = first;
  copying->factor(chain.base_blocks(), first);
  borrowing->factor_borrowing(base, springs);
  const Eigen::VectorXd x1 = copying->solve(b);
  EXPECT_EQ(borrowing->solve(b), x1);
  springs = second;
  copying->factor(chain.base_blocks(), second);
  borrowing->factor_borrowing(base, springs);
  const Eigen::VectorXd x2 = copying->solve(b);
  EXPECT_EQ(borrowing->solve(b), x2);
  const Eigen::VectorXd expected = chain.dense_with(second).llt().solve(b);
  EXPECT_LT((x2 - expected).norm(), 1e-10 * expected.norm());
  EXPECT_EQ(borrowing->counts().factorisations, copying->counts().factorisations);
  EXPECT_EQ(borrowing->counts().modified_terms, copying->counts().modified_terms);
}

// find_changed_terms walks both sorted lists once: what is new (in `now` only) and what is
// gone (in `before` only), in id order, the ones in both left out, at either list's end too;
// false once more than `limit` have changed.
TEST(LinearSolver, ChangedTermsAreThoseInOneListOnly) {
  const auto term = [](int block, int kind) {
    RankOneTerm t;
    t.id = {block, 0, block + 1, 0, kind};
    return t;
  };
  const RankOneTerms before{term(1, 0), term(2, 0), term(2, 1), term(5, 0)};
  const RankOneTerms now{term(0, 0), term(2, 0), term(3, 0), term(5, 0), term(7, 0), term(8, 1)};
  RankOneTerms added, removed;
  ASSERT_TRUE(find_changed_terms(now, before, 6, added, removed));
  const auto ids = [](const RankOneTerms& terms) {
    std::vector<std::array<int, 5>> out;
    for (const RankOneTerm& t : terms) out.push_back(t.id);
    return out;
  };
  EXPECT_EQ(ids(added), ids({term(0, 0), term(3, 0), term(7, 0), term(8, 1)}));
  EXPECT_EQ(ids(removed), ids({term(1, 0), term(2, 1)}));
  EXPECT_FALSE(find_changed_terms(now, before, 5, added, removed));  // six changed
  EXPECT_FALSE(find_changed_terms(now, {}, 5, added, removed));      // six new, all at the end
  EXPECT_TRUE(find_changed_terms(now, now, 0, added, removed));
  EXPECT_TRUE(added.empty() && removed.empty());
}

// Long lists (12,000 springs and more, enough for the two halves to run side by side): now
// holds springs on blocks 0 … 8,999 at random; before lacks every third of them and has 4,000
// of its own on blocks below 1,000, so that the two lists' middles by count lie far apart by
// id. The added and removed terms are exactly std::set_difference's, in id order. With the
// limit one below the number of changes, the answer is false.
TEST(LinearSolver, ChangedTermsOfLongListsAreThoseOfASetDifference) {
  std::mt19937 rng(17);
  const auto draw = [&](std::size_t count, int blocks) {
    std::set<std::array<int, 5>> ids;
    std::uniform_int_distribution<int> block(0, blocks - 1), kind(0, 1);
    while (ids.size() < count) ids.insert({block(rng), 0, block(rng), 0, kind(rng)});
    return ids;
  };
  const auto as_terms = [](const std::set<std::array<int, 5>>& ids) {
    RankOneTerms terms;
    for (const auto& id : ids) {
      RankOneTerm t;
      t.id = id;
      terms.push_back(t);
    }
    return terms;
  };
  const std::set<std::array<int, 5>> now_ids = draw(12000, 9000);
  std::set<std::array<int, 5>> before_ids = draw(4000, 1000);
  int k = 0;
  for (const auto& id : now_ids)
    if (k++ % 3 != 0) before_ids.insert(id);
  const RankOneTerms now = as_terms(now_ids), before = as_terms(before_ids);
  const auto by_id = [](const RankOneTerm& a, const RankOneTerm& b) { return a.id < b.id; };
  RankOneTerms expected_added, expected_removed;
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(expected_added), by_id);
  std::set_difference(before.begin(), before.end(), now.begin(), now.end(), std::back_inserter(expected_removed), by_id);
  const std::size_t changes = expected_added.size() + expected_removed.size();
  ASSERT_GT(changes, 5000u);
  RankOneTerms added, removed;
  ASSERT_TRUE(find_changed_terms(now, before, changes, added, removed));
  const auto ids = [](const RankOneTerms& terms) {
    std::vector<std::array<int, 5>> out;
    for (const RankOneTerm& t : terms) out.push_back(t.id);
    return out;
  };
  EXPECT_EQ(ids(added), ids(expected_added));
  EXPECT_EQ(ids(removed), ids(expected_removed));
  EXPECT_FALSE(find_changed_terms(now, before, changes - 1, added, removed));
}

// More springs changing at once than either solver follows (CHOLMOD: a quarter of the block
// count; the block solver: 64), here 80 new on 30 blocks: the solver factors afresh instead,
// and the answer is still A2⁻¹ b to 1e-10.
TEST_P(KeptFactor, ManySpringsChangingAtOnceAreFactoredAfresh) {
  ChainWithSprings chain;
  const RankOneTerms first{chain.make_term(1, 0, 1)};
  RankOneTerms second = first;
  for (int k = 0; k < 80; ++k) second.push_back(chain.make_term(2 + k, k % 29, k % 29 + 1));
  const Eigen::MatrixXd dense1 = chain.dense_with(first), dense2 = chain.dense_with(second);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(180, -1.0, 2.0);
  auto solver = GetParam().make();
  solver->factor(chain.base_blocks(), first);
  solver->solve(b);
  solver->factor(chain.base_blocks(), second);
  const Eigen::VectorXd x2 = dense2.llt().solve(b);
  EXPECT_LT((solver->solve(b) - x2).norm(), 1e-10 * x2.norm());
  EXPECT_EQ(solver->counts().factorisations, 2);
  EXPECT_EQ(solver->counts().modified_terms, 0);
}

}  // namespace
}  // namespace hydrodda::dda
