#pragma once
// Sparse Cholesky factorisation A = L Lᵀ of a symmetric positive definite block matrix, with
// 6×6 blocks as the unit of everything: pattern, elimination tree, arithmetic.
//
// Written by hand, not taken from CHOLMOD: a DDA matrix is a 2D block graph whose blocks are
// all dense 6×6, and working on the blocks (fixed-size kernels, one index per 36 values)
// factors and solves a 1,600-block wall's matrix in 16 ms where CHOLMOD's simplicial LDLᵀ
// takes 80 ms (bench_dda, BM_WallGraphFactorAndSolve), and the whole wall step is faster
// (BM_BrickWall against BM_BrickWallCholmod; docs/performance.md).

#include <vector>

#include <Eigen/Core>

#include "dda/block_matrix.hpp"

namespace hydrodda::dda {

class BlockCholesky {
 public:
  // Analyses and factors `a` with its blocks eliminated in `order` (order[k]: the block
  // eliminated k-th, a permutation of 0 … block_count − 1). False, leaving no factor, if a
  // pivot block is not positive definite.
  bool factorise(const BlockMatrix& a, const std::vector<int>& order);
  bool empty() const { return block_count_ == 0; }
  // x ← A⁻¹ x.
  void solve_in_place(Eigen::Ref<Eigen::VectorXd> x) const;
  // Off-diagonal 6×6 blocks of L: the fill.
  long off_diagonal_blocks() const { return static_cast<long>(row_.size()); }
  void clear();

 private:
  int block_count_ = 0;
  std::vector<int> order_;            // order_[k]: the block eliminated k-th
  std::vector<int> column_start_;     // L's block columns (positions), compressed
  std::vector<int> row_;
  std::vector<Matrix6> value_;
  std::vector<Matrix6> inverse_diagonal_;  // (L_kk)⁻¹, lower triangular
  mutable Eigen::VectorXd work_;
};

}  // namespace hydrodda::dda
