#include "numerics/supernodal_correction.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "numerics/blas_threads.hpp"
#include "numerics/woodbury.hpp"

namespace hydrodda::numerics {
namespace {

// Pseudocode (Hager, "Updating the inverse of a matrix", SIAM Review 31, 1989; the identity
// of numerics/woodbury.hpp, which dda/factor_solver.cpp uses too). CHOLMOD factors L Lᵀ = P A Pᵀ. With the
// columns scaled, Ũ = U |S|^½ and σ = sign S:
//   A + U S Uᵀ = Pᵀ L (I + W σ Wᵀ) Lᵀ P,        W = L⁻¹ P Ũ,
//   (A + U S Uᵀ)⁻¹ = Pᵀ L⁻ᵀ (I − W C⁻¹ Wᵀ) L⁻¹ P,   C = σ + Wᵀ W   (σ⁻¹ = σ).
// Column j of W is nonzero only on the supernodes on the paths from its rows up to the root
// of the supernodal elimination tree (Gilbert and Peierls' reach, by supernodes). W is kept
// as one dense block per supernode reached: the supernode's columns of L as rows, the columns
// of W that reach it as columns. One sweep up the tree computes it (CHOLMOD numbers
// supernodes children first):
//   for each reached supernode s, ascending:
//     X_s ← L_ss⁻¹ X_s                        its diagonal block, lower triangular
//     for each row i of s below that block, in supernode a:  X_a(i, J_s) −= L_is X_s
// and C = σ + Σ_s X_sᵀ X_s, each block's Gram matrix added over its columns J_s.
class SupernodalCorrection final : public CorrectedFactor {
 public:
  SupernodalCorrection(cholmod_factor* factor, cholmod_common* common, const SupernodalTree& tree,
                       const LowRankTerm& term, HalfSolves halves, const float* single);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;

 private:
  using Block = Eigen::Map<Eigen::MatrixXd>;
  struct Reached {        // W's rows in one supernode, for the columns of W that reach it
    int supernode;
    int first_column;     // its columns J_s: columns_[first_column, + column_count), ascending
    int column_count;
    std::size_t first_value;  // its block, column-major, as many rows as the supernode has columns
  };
  int width(int s) const { return super_[s + 1] - super_[s]; }
  int height(int s) const { return pi_[s + 1] - pi_[s]; }
  Block block(const Reached& r) {
    return Block(values_.data() + r.first_value, width(r.supernode), r.column_count);
  }
  Eigen::Map<const Eigen::MatrixXd> block(const Reached& r) const {
    return {values_.data() + r.first_value, width(r.supernode), r.column_count};
  }
  void find_reach(const LowRankTerm& term, const SupernodalTree& tree);
  void scatter_columns(const LowRankTerm& term, const SupernodalTree& tree);
  void sweep_up(const SupernodalTree& tree);
  void factor_capacitance(const LowRankTerm& term);
  void correct_half_solved(Eigen::VectorXd& y) const;
  // Applies a CHOLMOD solve of kind `system` (CHOLMOD_P, _L, _Lt, _Pt) to x in place.
  void apply(int system, Eigen::VectorXd& x) const;

  cholmod_factor* factor_;
  cholmod_common* common_;
  HalfSolves halves_;
  const int* super_;  // per supernode: its first column (nsuper + 1)
  const int* pi_;     // per supernode: its first row index in rows_ (nsuper + 1)
  const int* px_;     // per supernode: its first value in l_ (nsuper + 1)
  const int* rows_;   // the row indices of each supernode, its own columns first
  const double* l_;   // the values of each supernode, column-major, height(s) rows
  const float* single_;  // or those values in single precision (then l_ is null)
  std::vector<int> reached_of_;   // per supernode: its index in reached_, −1 if W misses it
  std::vector<Reached> reached_;  // ascending supernodes
  std::vector<int> columns_;
  std::vector<double> values_;
  numerics::WoodburyCapacitance capacitance_;
};

void check_supernodal(const cholmod_factor* factor) {
  if (!factor || !factor->is_super || !factor->is_ll || factor->itype != CHOLMOD_INT)
    throw std::logic_error("supernodal correction: needs a supernodal LLᵀ factor with int indices");
}

SupernodalCorrection::SupernodalCorrection(cholmod_factor* factor, cholmod_common* common, const SupernodalTree& tree,
                                           const LowRankTerm& term, HalfSolves halves, const float* single)
    : factor_(factor), common_(common), halves_(std::move(halves)), single_(single) {
  check_supernodal(factor_);
  if (!single_ && (factor_->xtype != CHOLMOD_REAL || factor_->dtype != CHOLMOD_DOUBLE))
    throw std::logic_error("supernodal correction: needs a numeric factor");
  if (single_ && (!halves_.forward || !halves_.backward))
    throw std::logic_error("supernodal correction: a factor in single precision needs its own half-solves");
  super_ = static_cast<const int*>(factor_->super);
  pi_ = static_cast<const int*>(factor_->pi);
  px_ = static_cast<const int*>(factor_->px);
  rows_ = static_cast<const int*>(factor_->s);
  l_ = single_ ? nullptr : static_cast<const double*>(factor_->x);
  if (tree.position.size() != factor_->n || tree.parent.size() != factor_->nsuper)
    throw std::logic_error("supernodal correction: the tree is another analysis's");
  if (static_cast<int>(term.start.size()) != term.columns() + 1)
    throw std::invalid_argument("supernodal correction: a low-rank term needs one start per column and one more");
  find_reach(term, tree);
  scatter_columns(term, tree);
  sweep_up(tree);
  factor_capacitance(term);
}

// The supernodes each column of W reaches, and its columns J_s per supernode.
void SupernodalCorrection::find_reach(const LowRankTerm& term, const SupernodalTree& tree) {
  const int nsuper = static_cast<int>(tree.parent.size());
  const int n = static_cast<int>(tree.position.size());
  std::vector<int> count(nsuper, 0), mark(nsuper, -1);
  const auto walk = [&](int j, auto&& visit) {
    for (int k = term.start[j]; k < term.start[j + 1]; ++k) {
      if (term.row[k] < 0 || term.row[k] >= n) throw std::out_of_range("supernodal correction: a row outside the matrix");
      for (int s = tree.supernode_of_column[tree.position[term.row[k]]]; s >= 0 && mark[s] != j; s = tree.parent[s]) {
        mark[s] = j;
        visit(s);
      }
    }
  };
  for (int j = 0; j < term.columns(); ++j) walk(j, [&](int s) { ++count[s]; });
  reached_of_.assign(nsuper, -1);
  int first_column = 0;
  std::size_t first_value = 0;
  for (int s = 0; s < nsuper; ++s) {
    if (count[s] == 0) continue;
    reached_of_[s] = static_cast<int>(reached_.size());
    reached_.push_back({s, first_column, 0, first_value});
    first_column += count[s];
    first_value += static_cast<std::size_t>(width(s)) * count[s];
  }
  columns_.resize(first_column);
  values_.assign(first_value, 0.0);
  std::fill(mark.begin(), mark.end(), -1);
  for (int j = 0; j < term.columns(); ++j)
    walk(j, [&](int s) {
      Reached& r = reached_[reached_of_[s]];
      columns_[r.first_column + r.column_count++] = j;  // j ascending: J_s sorted
    });
}

// Ũ = U |S|^½ into the blocks, rows in elimination positions.
void SupernodalCorrection::scatter_columns(const LowRankTerm& term, const SupernodalTree& tree) {
  for (int j = 0; j < term.columns(); ++j) {
    const double scale = std::sqrt(std::abs(term.weight[j]));
    for (int k = term.start[j]; k < term.start[j + 1]; ++k) {
      const int row = tree.position[term.row[k]];
      const int s = tree.supernode_of_column[row];
      const Reached& r = reached_[reached_of_[s]];
      const int* first = &columns_[r.first_column];
      const int at = static_cast<int>(std::lower_bound(first, first + r.column_count, j) - first);
      block(r)(row - super_[s], at) += scale * term.value[k];
    }
  }
}

void SupernodalCorrection::sweep_up(const SupernodalTree& tree) {
  Eigen::MatrixXd update;
  Eigen::MatrixXd widened;  // a supernode's values of L̃ in double: exactly L̃'s
  std::vector<int> at;  // J_s's positions in J_a
  for (const Reached& r : reached_) {
    const int s = r.supernode, nscol = width(s), below = height(s) - nscol;
    Block x = block(r);
    if (single_) widened = Eigen::Map<const Eigen::MatrixXf>(single_ + px_[s], height(s), nscol).cast<double>();
    const Eigen::Map<const Eigen::MatrixXd> l(single_ ? widened.data() : l_ + px_[s], height(s), nscol);
    l.topRows(nscol).triangularView<Eigen::Lower>().solveInPlace(x);
    if (below == 0) continue;
    update.noalias() = l.bottomRows(below) * x;
    const int* row = rows_ + pi_[s] + nscol;
    for (int i = 0; i < below;) {
      const int a = tree.supernode_of_column[row[i]];
      const Reached& ra = reached_[reached_of_[a]];  // a is on every path through s
      const int* ja = &columns_[ra.first_column];
      at.resize(r.column_count);
      for (int c = 0, p = 0; c < r.column_count; ++c) {
        while (ja[p] != columns_[r.first_column + c]) ++p;
        at[c] = p;
      }
      Block xa = block(ra);
      for (; i < below && row[i] < super_[a + 1]; ++i)
        for (int c = 0; c < r.column_count; ++c) xa(row[i] - super_[a], at[c]) -= update(i, c);
    }
  }
}

void SupernodalCorrection::factor_capacitance(const LowRankTerm& term) {
  const int m = term.columns();
  if (m == 0) return;
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(m, m);
  for (int j = 0; j < m; ++j) c(j, j) = term.weight[j] < 0.0 ? -1.0 : 1.0;
  Eigen::MatrixXd gram;
  for (const Reached& r : reached_) {
    const auto x = block(r);
    gram.noalias() = x.transpose() * x;
    const int* j = &columns_[r.first_column];
    for (int q = 0; q < r.column_count; ++q)
      for (int p = 0; p < r.column_count; ++p) c(j[p], j[q]) += gram(p, q);
  }
  capacitance_.factor(c);
  if (capacitance_.singular(1e-14))
    throw SingularSystem("supernodal correction: the corrected matrix is singular to working precision");
}

void SupernodalCorrection::apply(int system, Eigen::VectorXd& x) const {
  cholmod_dense b{};
  b.nrow = b.d = static_cast<size_t>(x.size());
  b.ncol = 1;
  b.nzmax = b.nrow;
  b.x = x.data();
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* out = nullptr;
  {
    const std::unique_lock<std::mutex> blas = hold_blas();
    out = cholmod_solve(system, factor_, &b, common_);
  }
  if (!out) throw SingularSystem("supernodal correction: CHOLMOD's solve failed");
  x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(out->x), x.size());
  cholmod_free_dense(&out, common_);
}

Eigen::VectorXd SupernodalCorrection::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd y = b;
  if (halves_.forward) {
    halves_.forward(y);
  } else {
    apply(CHOLMOD_P, y);
    apply(CHOLMOD_L, y);
  }
  if (!reached_.empty()) correct_half_solved(y);
  if (halves_.backward) {
    halves_.backward(y);
  } else {
    apply(CHOLMOD_Lt, y);
    apply(CHOLMOD_Pt, y);
  }
  return y;
}

// y ← y − W C⁻¹ Wᵀ y
void SupernodalCorrection::correct_half_solved(Eigen::VectorXd& y) const {
  Eigen::VectorXd t = Eigen::VectorXd::Zero(capacitance_.size());
  for (const Reached& r : reached_) {
    const Eigen::VectorXd part = block(r).transpose() * y.segment(super_[r.supernode], width(r.supernode));
    for (int c = 0; c < r.column_count; ++c) t[columns_[r.first_column + c]] += part[c];
  }
  const Eigen::VectorXd v = capacitance_.solve(t);
  Eigen::VectorXd vs;
  for (const Reached& r : reached_) {
    vs.resize(r.column_count);
    for (int c = 0; c < r.column_count; ++c) vs[c] = v[columns_[r.first_column + c]];
    y.segment(super_[r.supernode], width(r.supernode)).noalias() -= block(r) * vs;
  }
}

}  // namespace

SupernodalTree make_supernodal_tree(const cholmod_factor* factor) {
  check_supernodal(factor);
  const int* super = static_cast<const int*>(factor->super);
  const int* pi = static_cast<const int*>(factor->pi);
  const int* rows = static_cast<const int*>(factor->s);
  const int* perm = static_cast<const int*>(factor->Perm);
  const int n = static_cast<int>(factor->n), nsuper = static_cast<int>(factor->nsuper);
  SupernodalTree tree;
  tree.supernode_of_column.resize(n);
  for (int s = 0; s < nsuper; ++s)
    std::fill(&tree.supernode_of_column[super[s]], &tree.supernode_of_column[super[s + 1]], s);
  // A supernode's parent holds the first row below its diagonal block.
  tree.parent.assign(nsuper, -1);
  for (int s = 0; s < nsuper; ++s) {
    const int width = super[s + 1] - super[s], height = pi[s + 1] - pi[s];
    if (height > width) tree.parent[s] = tree.supernode_of_column[rows[pi[s] + width]];
  }
  // L Lᵀ = P A Pᵀ with Perm[k] the unknown eliminated k-th.
  tree.position.resize(n);
  for (int k = 0; k < n; ++k) tree.position[perm[k]] = k;
  return tree;
}

std::unique_ptr<CorrectedFactor> correct_supernodal_factor(cholmod_factor* factor, cholmod_common* common,
                                                           const SupernodalTree& tree, const LowRankTerm& term,
                                                           HalfSolves halves, const float* single) {
  return std::make_unique<SupernodalCorrection>(factor, common, tree, term, std::move(halves), single);
}

}  // namespace hydrodda::numerics
