#include "dda/block_matrix.hpp"

#include <algorithm>
#include <map>

#include <Eigen/OrderingMethods>

namespace hydrodda::dda {

void BlockMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.resize(size());
  multiply_rows(x, y, 0, block_count);
}

void BlockMatrix::multiply_rows(const Eigen::VectorXd& x, Eigen::VectorXd& y, int first, int last) const {
  const auto mine = [&](int b) { return b >= first && b < last; };
  for (int b = first; b < last; ++b) y.segment<6>(6 * b).noalias() = diagonal[b] * x.segment<6>(6 * b);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto [col, row] = pairs[p];
    if (mine(row)) y.segment<6>(6 * row).noalias() += off[p] * x.segment<6>(6 * col);
    if (mine(col)) y.segment<6>(6 * col).noalias() += off[p].transpose() * x.segment<6>(6 * row);
  }
}

bool BlockMatrix::all_finite() const {
  const auto finite = [](const Matrix6& m) { return m.allFinite(); };
  return std::all_of(diagonal.begin(), diagonal.end(), finite) && std::all_of(off.begin(), off.end(), finite);
}

SparseMatrix BlockMatrix::lower_triangle() const {
  // Column by column: the diagonal block's lower part, then the off-diagonal blocks of that
  // block column in row order (pairs are sorted by column, then row).
  std::vector<int> first_pair(block_count + 1, 0);
  for (auto [col, row] : pairs) ++first_pair[col + 1];
  for (int b = 0; b < block_count; ++b) first_pair[b + 1] += first_pair[b];
  const int n = size();
  SparseMatrix k(n, n);
  k.resizeNonZeros(block_count * 21 + static_cast<int>(pairs.size()) * 36);
  int* outer = k.outerIndexPtr();
  int* inner = k.innerIndexPtr();
  double* value = k.valuePtr();
  int nz = 0;
  for (int b = 0; b < block_count; ++b) {
    for (int c = 0; c < 6; ++c) {
      outer[6 * b + c] = nz;
      for (int r = c; r < 6; ++r) {
        inner[nz] = 6 * b + r;
        value[nz++] = diagonal[b](r, c);
      }
      for (int p = first_pair[b]; p < first_pair[b + 1]; ++p) {
        const int row = pairs[p].second;
        for (int r = 0; r < 6; ++r) {
          inner[nz] = 6 * row + r;
          value[nz++] = off[p](r, c);
        }
      }
    }
  }
  outer[n] = nz;
  return k;
}

std::vector<int> order_by_minimum_degree(const BlockMatrix& a) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(a.block_count + 2 * a.pairs.size());
  for (int b = 0; b < a.block_count; ++b) entries.emplace_back(b, b, 1.0);
  for (auto [i, j] : a.pairs) {
    entries.emplace_back(i, j, 1.0);
    entries.emplace_back(j, i, 1.0);
  }
  SparseMatrix graph(a.block_count, a.block_count);
  graph.setFromTriplets(entries.begin(), entries.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
  Eigen::AMDOrdering<int>()(graph, inverse);
  // Eigen's orderings give the inverse permutation: position k → the block eliminated k-th.
  return {inverse.indices().data(), inverse.indices().data() + a.block_count};
}

BlockMatrix block_form(const SparseMatrix& lower, int block_count) {
  BlockMatrix a;
  a.block_count = block_count;
  a.diagonal.assign(block_count, Matrix6::Zero());
  std::map<std::pair<int, int>, Matrix6> off;
  for (int j = 0; j < lower.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(lower, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (i < j) continue;
      const int bi = i / 6, bj = j / 6;
      if (bi == bj) {
        a.diagonal[bi](i % 6, j % 6) = it.value();
        a.diagonal[bi](j % 6, i % 6) = it.value();
      } else {
        off.try_emplace({bj, bi}, Matrix6::Zero()).first->second(i % 6, j % 6) = it.value();
      }
    }
  for (const auto& [pair, block] : off) {
    a.pairs.push_back(pair);
    a.off.push_back(block);
  }
  return a;
}

}  // namespace hydrodda::dda
