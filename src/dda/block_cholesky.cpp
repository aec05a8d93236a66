#include "dda/block_cholesky.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace hydrodda::dda {

namespace {

// One entry of row k of the permuted lower triangle: column j < k, and the matrix's block
// that holds A'(k, j), transposed if the permutation swapped its row and column.
struct RowEntry {
  int column;
  int pair;
  bool transposed;
};

}  // namespace

void BlockCholesky::clear() {
  block_count_ = 0;
  order_.clear();
  column_start_.clear();
  row_.clear();
  value_.clear();
  inverse_diagonal_.clear();
}

// Up-looking (row by row) Cholesky over blocks; Davis, "Direct Methods for Sparse Linear
// Systems" (SIAM 2006), §4.1 (elimination tree), §4.2 (row patterns by ereach), §4.8 (cs_chol),
// with every scalar become a 6×6 block:
//   parent ← etree(A);  column counts ← for each row k, the nodes ereach(k) reaches
//   for k = 0 … n−1:
//     X_j ← A(k, j) for j < k;  D ← A(k, k)
//     for i in ereach(k), children before parents:
//       L(k, i) ← X_i L(i, i)⁻ᵀ;  X_r −= L(k, i) L(r, i)ᵀ for the rows r < k of column i
//       D −= L(k, i) L(k, i)ᵀ
//     L(k, k) ← chol(D)   (fails if D is not positive definite)
bool BlockCholesky::factorise(const BlockMatrix& a, const std::vector<int>& order) {
  clear();
  const int n = a.block_count;
  std::vector<int> position(n);
  for (int k = 0; k < n; ++k) position[order[k]] = k;

  // Rows of the permuted strictly lower triangle, by counting sort.
  std::vector<int> row_start(n + 1, 0);
  for (auto [col, row] : a.pairs) ++row_start[std::max(position[col], position[row]) + 1];
  for (int k = 0; k < n; ++k) row_start[k + 1] += row_start[k];
  std::vector<RowEntry> rows(a.pairs.size());
  {
    std::vector<int> next(row_start.begin(), row_start.end() - 1);
    for (std::size_t p = 0; p < a.pairs.size(); ++p) {
      const int pc = position[a.pairs[p].first], pr = position[a.pairs[p].second];
      // off[p] is A(row, column): it is A'(pr, pc) as stored, or its transpose if pc > pr.
      if (pr > pc)
        rows[next[pr]++] = {pc, static_cast<int>(p), false};
      else
        rows[next[pc]++] = {pr, static_cast<int>(p), true};
    }
  }

  // Elimination tree, in elimination positions (Liu's algorithm with path compression
  // through `ancestor`).
  std::vector<int> parent(n, -1);
  {
    std::vector<int> ancestor(n, -1);
    for (int k = 0; k < n; ++k)
      for (int e = row_start[k]; e < row_start[k + 1]; ++e)
        for (int i = rows[e].column; i != -1 && i < k;) {
          const int next = ancestor[i];
          ancestor[i] = k;
          if (next == -1) parent[i] = k;
          i = next;
        }
  }

  // ereach(k): the row pattern of L(k, :), on the stack[top … n−1], children first.
  std::vector<int> mark(n, -1), stack(n), path(n);
  const auto reach = [&](int k) {
    int top = n;
    mark[k] = k;
    for (int e = row_start[k]; e < row_start[k + 1]; ++e) {
      int length = 0;
      for (int i = rows[e].column; mark[i] != k; i = parent[i]) {
        path[length++] = i;
        mark[i] = k;
      }
      while (length > 0) stack[--top] = path[--length];
    }
    return top;
  };

  // Column counts, then the numeric factorisation into the allocated columns.
  column_start_.assign(n + 1, 0);
  for (int k = 0; k < n; ++k)
    for (int top = reach(k); top < n; ++top) ++column_start_[stack[top] + 1];
  for (int k = 0; k < n; ++k) column_start_[k + 1] += column_start_[k];
  row_.resize(column_start_[n]);
  value_.resize(column_start_[n]);
  inverse_diagonal_.resize(n);
  std::vector<int> filled(column_start_.begin(), column_start_.end() - 1);
  std::vector<Matrix6> x(n, Matrix6::Zero());
  std::fill(mark.begin(), mark.end(), -1);
  for (int k = 0; k < n; ++k) {
    const int top = reach(k);
    for (int e = row_start[k]; e < row_start[k + 1]; ++e) {
      const Matrix6& block = a.off[rows[e].pair];
      if (rows[e].transposed)
        x[rows[e].column] = block.transpose();
      else
        x[rows[e].column] = block;
    }
    Matrix6 d = a.diagonal[order[k]];
    for (int s = top; s < n; ++s) {
      const int i = stack[s];
      const Matrix6 lki = x[i] * inverse_diagonal_[i].transpose();
      x[i].setZero();
      for (int q = column_start_[i]; q < filled[i]; ++q) x[row_[q]].noalias() -= lki * value_[q].transpose();
      d.noalias() -= lki * lki.transpose();
      row_[filled[i]] = k;
      value_[filled[i]++] = lki;
    }
    const Eigen::LLT<Matrix6> llt(d);
    if (llt.info() != Eigen::Success || !std::isfinite(d.trace())) {
      clear();
      return false;
    }
    inverse_diagonal_[k] = llt.matrixL().solve(Matrix6::Identity());
  }
  order_ = order;
  block_count_ = n;
  return true;
}

// L y = P b forward by columns, then Lᵀ z = y backward by rows, x = Pᵀ z.
void BlockCholesky::solve_in_place(Eigen::Ref<Eigen::VectorXd> x) const {
  const int n = block_count_;
  work_.resize(6 * n);
  for (int k = 0; k < n; ++k) work_.segment<6>(6 * k) = x.segment<6>(6 * order_[k]);
  for (int k = 0; k < n; ++k) {
    // The inverse is lower triangular; a full fixed-size product is faster than a triangular one.
    const Eigen::Matrix<double, 6, 1> yk = inverse_diagonal_[k] * work_.segment<6>(6 * k);
    work_.segment<6>(6 * k) = yk;
    for (int q = column_start_[k]; q < column_start_[k + 1]; ++q)
      work_.segment<6>(6 * row_[q]).noalias() -= value_[q] * yk;
  }
  for (int k = n - 1; k >= 0; --k) {
    Eigen::Matrix<double, 6, 1> t = work_.segment<6>(6 * k);
    for (int q = column_start_[k]; q < column_start_[k + 1]; ++q)
      t.noalias() -= value_[q].transpose() * work_.segment<6>(6 * row_[q]);
    work_.segment<6>(6 * k).noalias() = inverse_diagonal_[k].transpose() * t;
  }
  for (int k = 0; k < n; ++k) x.segment<6>(6 * order_[k]) = work_.segment<6>(6 * k);
}

}  // namespace hydrodda::dda
