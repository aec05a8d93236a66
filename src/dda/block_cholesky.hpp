#pragma once
// Sparse Cholesky factorisation A = L Lᵀ of a symmetric positive definite block matrix, with
// 6×6 blocks as the unit of everything: pattern, elimination tree, arithmetic.
//
// Written by hand, not taken from CHOLMOD: a DDA matrix is a 2D block graph whose blocks are
// all dense 6×6, and working on the blocks (fixed-size kernels, one index per 36 values)
// factors and solves a 1,600-block wall's matrix in 16 ms where CHOLMOD's simplicial LDLᵀ
// takes 80 ms (bench_dda, BM_WallGraphFactorAndSolve), and the whole wall step is faster
// (BM_BrickWall against BM_BrickWallCholmod; docs/performance.md).

#include <array>
#include <vector>

#include <Eigen/Core>

#include "dda/block_matrix.hpp"
#include "dda/linear_solver.hpp"

namespace hydrodda::dda {

class BlockCholesky {
 public:
  // Analyses and factors `a` with its blocks eliminated in `order` (order[k]: the block
  // eliminated k-th, a permutation of 0 … block_count − 1). False, leaving no factor, if a
  // pivot block is not positive definite.
  bool factorise(const BlockMatrix& a, const std::vector<int>& order);
  // The same for a + Σ w wᵀ over the springs, read where they are: no assembled matrix, whose
  // memory a first factorisation would touch afresh.
  bool factorise(const BlockMatrix& a, const RankOneTerms& springs, const std::vector<int>& order);
  bool empty() const { return block_count_ == 0; }
  // x ← A⁻¹ x.
  void solve_in_place(Eigen::Ref<Eigen::VectorXd> x) const;

  // The two halves of a solve, A⁻¹ = Pᵀ L⁻ᵀ L⁻¹ P, for a caller that works between them: u in
  // elimination order (block k of u is the block eliminated k-th).
  void forward(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& u) const;  // u = L⁻¹ P x
  void backward(Eigen::VectorXd& u, Eigen::Ref<Eigen::VectorXd> x) const;  // x = Pᵀ L⁻ᵀ u; u is spent

  // A vector nonzero on a few blocks: (block or position, 6 values), positions ascending.
  struct SparseVector {
    std::vector<int> blocks;
    std::vector<Vector6> values;
  };
  // L⁻¹ P b for a b nonzero on a few blocks, in elimination positions. Its nonzeros lie on the
  // paths from b's blocks to the root of the elimination tree, so this costs a path, not the
  // whole factor (Gilbert & Peierls 1988; Davis 2006, §3.2).
  SparseVector forward_sparse(const SparseVector& b) const;
  // The block kernels by hand with AVX2 and FMA (on by default where the CPU has them) or
  // portable; the answer is the same to round-off. Returns whether the vectorised ones are
  // now in use. For tests and benchmarks that compare the two.
  static bool use_vectorised_kernels(bool on);
  // The factor's arrays as the triangular-sweep kernels take them (defined with them).
  struct Sweep;
  // Off-diagonal 6×6 blocks of L: the fill.
  long off_diagonal_blocks() const { return static_cast<long>(row_.size()); }
  // The factor's work (blocks of L, diagonal included) in each of the two parts of the
  // elimination tree that run side by side, and in the top that runs after them.
  std::array<long, 3> part_blocks() const;
  void clear();

 private:
  int block_count_ = 0;
  std::vector<int> order_;            // order_[k]: the block eliminated k-th
  std::vector<int> column_start_;     // L's block columns (positions), compressed
  std::vector<int> row_;
  Matrix6Array value_;
  Matrix6Array inverse_diagonal_;  // (L_kk)⁻¹, lower triangular
  std::vector<int> position_;               // position_[b]: where block b is eliminated
  std::vector<int> parent_;                 // elimination tree, in positions; −1 at a root
  // Two parts of the elimination tree, each a set of whole subtrees, that share no column,
  // and the top: the ancestors of both (split_elimination_tree). The factorisation and both
  // sweeps do the two parts side by side, on two threads where there are two, and the top
  // after them; the arithmetic is the same on one thread or two.
  std::array<std::vector<int>, 3> part_columns_;  // positions ascending: part 0, part 1, top
  std::vector<int> top_index_;                    // position → index among the top's; −1 below
  std::vector<int> top_rows_start_;               // position → first of its column's top rows
  mutable std::array<Eigen::VectorXd, 2> top_updates_;  // each part's forward updates to the top
  mutable Eigen::VectorXd work_;
  mutable Eigen::VectorXd path_work_;       // zero but during forward_sparse
  mutable std::vector<char> on_path_;       // likewise
  // The numeric factorisation's rows and working arrays while it runs (block_cholesky.cpp).
  class Elimination;
  Sweep sweep() const;
  void split_elimination_tree();
  // The forward sweep's split of each part's columns, and the solves' work arrays.
  void prepare_sweeps(const std::vector<int>& order);
  // Whether a factor this size pays for a second thread.
  bool run_parts_in_parallel() const;
};

}  // namespace hydrodda::dda
