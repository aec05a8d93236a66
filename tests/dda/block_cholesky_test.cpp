// The block Cholesky factorisation against a dense one, its fill against what elimination
// theory says it must be, its refusal of a matrix that is not positive definite, and its
// split into two parts that run side by side.

#include "dda/block_cholesky.hpp"
#include "dda/linear_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include <Eigen/Dense>
#include <omp.h>

#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

// A symmetric positive definite block matrix on the given block graph (test_models.hpp),
// and its dense form.
BlockMatrix make_matrix(int n, const std::set<std::pair<int, int>>& graph, Eigen::MatrixXd& dense) {
  BlockMatrix a = testing::make_block_graph_matrix(n, {graph.begin(), graph.end()}, 11);
  const Eigen::MatrixXd lower(a.lower_triangle());
  dense = lower.selfadjointView<Eigen::Lower>();
  return a;
}

// Blocks 0 … n−1 joined each to the next.
std::set<std::pair<int, int>> chain_graph(int n) {
  std::set<std::pair<int, int>> chain;
  for (int b = 0; b + 1 < n; ++b) chain.emplace(b, b + 1);
  return chain;
}

std::vector<int> natural_order(int n) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

// The tests below run with the portable kernels and, where the CPU has AVX2 and FMA, the
// vectorised ones.
class BlockCholeskyKernels : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (BlockCholesky::use_vectorised_kernels(GetParam()) != GetParam())
      GTEST_SKIP() << "this CPU lacks AVX2 or FMA";
  }
  void TearDown() override { BlockCholesky::use_vectorised_kernels(true); }
};
INSTANTIATE_TEST_SUITE_P(BlockCholesky, BlockCholeskyKernels, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "vectorised" : "portable"; });

// A random graph of 40 blocks and 90 pairs, factored in three orders (natural, reversed,
// random): A⁻¹ b agrees with a dense LLᵀ solve to 1e-10 relative, far above round-off for a
// matrix this well conditioned, far below any error in the factor.
TEST_P(BlockCholeskyKernels, SolvesAsADenseFactorDoes) {
  const int n = 40;
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::set<std::pair<int, int>> graph;
  while (graph.size() < 90) {
    const int i = pick(rng), j = pick(rng);
    if (i != j) graph.emplace(std::min(i, j), std::max(i, j));
  }
  Eigen::MatrixXd dense;
  const BlockMatrix a = make_matrix(n, graph, dense);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(6 * n, -1.0, 3.0);
  const Eigen::VectorXd expected = dense.llt().solve(b);
  std::vector<int> reversed = natural_order(n);
  std::reverse(reversed.begin(), reversed.end());
  std::vector<int> shuffled = natural_order(n);
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  for (const auto& order : {natural_order(n), reversed, shuffled}) {
    BlockCholesky factor;
    ASSERT_TRUE(factor.factorise(a, order));
    Eigen::VectorXd x = b;
    factor.solve_in_place(x);
    EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
  }
}

// The half-solves: forward gives u = L⁻¹ P b, so uᵀu = bᵀ A⁻¹ b (checked against the dense
// solve, 1e-10 relative), and backward of it is A⁻¹ b. A b nonzero on two blocks solved
// sparsely gives the same u (1e-12 relative) with nonzeros only on the blocks' paths, fewer
// than all the blocks.
TEST_P(BlockCholeskyKernels, HalfSolvesAndASparseForwardSolveAgree) {
  const int n = 40;
  std::set<std::pair<int, int>> chain = chain_graph(n);
  for (int b = 0; b + 5 < n; b += 5) chain.emplace(b, b + 5);
  Eigen::MatrixXd dense;
  const BlockMatrix a = make_matrix(n, chain, dense);
  BlockCholesky factor;
  ASSERT_TRUE(factor.factorise(a, order_by_minimum_degree(a)));
  Eigen::VectorXd b = Eigen::VectorXd::Zero(6 * n);
  BlockCholesky::SparseVector sparse;
  sparse.blocks = {7, 31};
  sparse.values = {Vector6::LinSpaced(-1.0, 2.0), Vector6::Constant(0.5)};
  b.segment<6>(6 * 7) = sparse.values[0];
  b.segment<6>(6 * 31) = sparse.values[1];
  const Eigen::VectorXd expected = dense.llt().solve(b);
  Eigen::VectorXd u;
  factor.forward(b, u);
  EXPECT_NEAR(u.squaredNorm(), b.dot(expected), 1e-10 * b.dot(expected));
  const BlockCholesky::SparseVector y = factor.forward_sparse(sparse);
  EXPECT_LT(static_cast<int>(y.blocks.size()), n);
  Eigen::VectorXd from_sparse = Eigen::VectorXd::Zero(6 * n);
  for (std::size_t e = 0; e < y.blocks.size(); ++e) from_sparse.segment<6>(6 * y.blocks[e]) = y.values[e];
  EXPECT_LT((from_sparse - u).norm(), 1e-12 * u.norm());
  Eigen::VectorXd x(6 * n);
  factor.backward(u, x);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

// Fill is exactly what the elimination graph predicts: a chain eliminated end to end has
// none (L's pattern is A's, n − 1 blocks); a star eliminated centre first fills completely
// (every leaf joins every later leaf: (n − 1) + (n − 1)(n − 2)/2 blocks).
TEST(BlockCholesky, FillIsThatOfTheEliminationGraph) {
  const int n = 12;
  const std::set<std::pair<int, int>> chain = chain_graph(n);
  std::set<std::pair<int, int>> star;
  for (int b = 1; b < n; ++b) star.emplace(0, b);
  Eigen::MatrixXd dense;
  BlockCholesky factor;
  ASSERT_TRUE(factor.factorise(make_matrix(n, chain, dense), natural_order(n)));
  EXPECT_EQ(factor.off_diagonal_blocks(), n - 1);
  ASSERT_TRUE(factor.factorise(make_matrix(n, star, dense), natural_order(n)));
  EXPECT_EQ(factor.off_diagonal_blocks(), (n - 1) + (n - 1) * (n - 2) / 2);
  // The star's centre last: no fill.
  std::vector<int> centre_last = natural_order(n);
  std::rotate(centre_last.begin(), centre_last.begin() + 1, centre_last.end());
  ASSERT_TRUE(factor.factorise(make_matrix(n, star, dense), centre_last));
  EXPECT_EQ(factor.off_diagonal_blocks(), n - 1);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(6 * n);
  const Eigen::VectorXd expected = dense.llt().solve(x);
  factor.solve_in_place(x);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

// A wall's matrix (14 × 14 blocks) splits into two parts and a top, whose rows are done in
// two phases (each part's columns eliminated from them side by side, then the top's own):
// A⁻¹ b agrees with a dense LLᵀ solve to 1e-10 relative, as in the test above.
TEST_P(BlockCholeskyKernels, ATreeSplitWithATopSolvesAsADenseFactorDoes) {
  const BlockMatrix a = testing::make_wall_graph_matrix(14);
  const Eigen::MatrixXd lower(a.lower_triangle());
  const Eigen::MatrixXd dense = lower.selfadjointView<Eigen::Lower>();
  BlockCholesky factor;
  ASSERT_TRUE(factor.factorise(a, order_by_minimum_degree(a)));
  const auto parts = factor.part_blocks();
  ASSERT_GT(parts[0], 0);
  ASSERT_GT(parts[1], 0);
  ASSERT_GT(parts[2], 1);  // a top of more than one block: its rows meet both parts and itself
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.size(), -2.0, 1.0);
  const Eigen::VectorXd expected = dense.llt().solve(b);
  Eigen::VectorXd x = b;
  factor.solve_in_place(x);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

// Springs read where they are give the factor of the assembled matrix: a wall's matrix
// (14 × 14 blocks, its tree split with a top) and 600 springs w wᵀ of every kind (joining two
// blocks, several on one pair, on one block only, on one block from both sides): A⁻¹ b from
// factorise(a, springs) agrees with the factor of add_springs(a, springs) and with a dense
// LLᵀ of the assembled matrix to 1e-10 relative (different sums of the same terms; round-off
// is far below).
TEST(BlockCholesky, SpringsReadInPlaceGiveTheAssembledFactor) {
  const BlockMatrix a = testing::make_wall_graph_matrix(14);
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> block(0, a.block_count - 1), kind(0, 9);
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  RankOneTerms springs;
  for (int q = 0; q < 600; ++q) {
    RankOneTerm t;
    t.id = {q, 0, 0, 0, 0};
    const int k = kind(rng);
    if (k < 3 && q > 0) {  // another on the pair of the spring before
      t.block_a = springs[q - 1].block_a;
      t.block_b = springs[q - 1].block_b;
    } else {
      t.block_a = block(rng);
      t.block_b = k == 3 ? -1 : k == 4 ? t.block_a : block(rng);  // one block; both sides on one
    }
    for (int i = 0; i < 6; ++i) {
      t.w_a[i] = value(rng);
      t.w_b[i] = value(rng);
    }
    springs.push_back(t);
  }
  const BlockMatrix assembled = add_springs(a, springs);
  const Eigen::MatrixXd lower(assembled.lower_triangle());
  const Eigen::MatrixXd dense = lower.selfadjointView<Eigen::Lower>();
  const std::vector<int> order = order_by_minimum_degree(a, springs);
  EXPECT_EQ(order, order_by_minimum_degree(assembled));
  BlockCholesky in_place, from_assembled;
  ASSERT_TRUE(in_place.factorise(a, springs, order));
  ASSERT_TRUE(from_assembled.factorise(assembled, order));
  ASSERT_GT(in_place.part_blocks()[2], 1);
  EXPECT_EQ(in_place.off_diagonal_blocks(), from_assembled.off_diagonal_blocks());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.size(), -1.0, 2.5);
  const Eigen::VectorXd expected = dense.llt().solve(b);
  Eigen::VectorXd x = b, y = b;
  in_place.solve_in_place(x);
  from_assembled.solve_in_place(y);
  EXPECT_LT((x - y).norm(), 1e-10 * y.norm());
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

// A matrix with a negative eigenvalue (one diagonal entry of a chain turned to −100) is
// refused, and no factor is left to be used.
TEST(BlockCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  const int n = 6;
  Eigen::MatrixXd dense;
  BlockMatrix a = make_matrix(n, chain_graph(n), dense);
  a.diagonal[3](2, 2) = -100.0;
  BlockCholesky factor;
  EXPECT_FALSE(factor.factorise(a, natural_order(n)));
  EXPECT_TRUE(factor.empty());
}

// The same refusal where the bad pivot is the last eliminated, the root, in the top of a split
// tree (a wall's matrix, 14 × 14 blocks).
TEST(BlockCholesky, RefusesAMatrixWhoseTopIsNotPositiveDefinite) {
  BlockMatrix a = testing::make_wall_graph_matrix(14);
  const std::vector<int> order = order_by_minimum_degree(a);
  BlockCholesky factor;
  ASSERT_TRUE(factor.factorise(a, order));
  ASSERT_GT(factor.part_blocks()[2], 0);
  a.diagonal[order.back()](0, 0) = -100.0;
  EXPECT_FALSE(factor.factorise(a, order));
  EXPECT_TRUE(factor.empty());
}

// The elimination tree of a 1,600-block wall's matrix is split into two parts that share no
// column and the top above them, so that the factorisation and the sweeps do the parts side by
// side. The split covers the factor (its blocks of L add up to L's, diagonal included), its
// parts are balanced within 10% of each other, and the top, which waits for both, holds under
// 10% of the work (measured: 15,040 and 14,582 blocks, top 1,081).
TEST(BlockCholesky, SplitsTheEliminationTreeIntoTwoBalancedParts) {
  const BlockMatrix a = testing::make_wall_graph_matrix(40);
  BlockCholesky factor;
  ASSERT_TRUE(factor.factorise(a, order_by_minimum_degree(a)));
  const auto parts = factor.part_blocks();
  const long total = parts[0] + parts[1] + parts[2];
  EXPECT_EQ(total, factor.off_diagonal_blocks() + a.block_count);
  EXPECT_LT(std::max(parts[0], parts[1]), 1.1 * std::min(parts[0], parts[1]));
  EXPECT_LT(parts[2], 0.1 * total);
}

// One thread or two: the factor and the solve are the same to the last bit, as each part's
// arithmetic is the same whichever thread does it. The solve is also right: ‖A x − b‖ ≤
// 1e-10 ‖b‖ (a well-conditioned matrix; round-off is far below).
TEST(BlockCholesky, OneThreadOrTwoGiveTheSameBits) {
  const BlockMatrix a = testing::make_wall_graph_matrix(40);
  const std::vector<int> order = order_by_minimum_degree(a);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.size(), -1.0, 2.0);
  const int threads_before = omp_get_max_threads();
  std::vector<Eigen::VectorXd> solutions;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    BlockCholesky factor;
    ASSERT_TRUE(factor.factorise(a, order));
    Eigen::VectorXd x = b;
    factor.solve_in_place(x);
    solutions.push_back(x);
  }
  omp_set_num_threads(threads_before);
  EXPECT_EQ(solutions[0], solutions[1]);
  Eigen::VectorXd ax;
  a.multiply(solutions[1], ax);
  EXPECT_LT((ax - b).norm(), 1e-10 * b.norm());
}

}  // namespace
}  // namespace hydrodda::dda
