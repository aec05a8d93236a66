#include "numerics/supernodal_factorization.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "numerics/parallel.hpp"
#include "numerics/blas_threads.hpp"

namespace hydrodda::numerics {

// Fortran BLAS and LAPACK, as CHOLMOD calls them (OpenBLAS on Debian; two threads call it at
// once only where blas_threads.cpp guards its buffers, else under hold_blas()).
extern "C" {
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace {

constexpr int kSeparator = 2;

const cholmod_factor* checked_analysis(const cholmod_factor* factor) {
  if (!factor || !factor->is_super || factor->itype != CHOLMOD_INT || !factor->Perm)
    throw std::logic_error("supernodal factorisation: needs CHOLMOD's supernodal analysis with int indices");
  return factor;
}

}  // namespace

SupernodalFactorization::SupernodalFactorization(cholmod_factor* factor, cholmod_common* common,
                                                 const SparseMatrix& upper, std::span<const int> part)
    : factor_(factor), common_(common), tree_(make_supernodal_tree(checked_analysis(factor))) {
  n_ = static_cast<int>(factor_->n);
  nsuper_ = static_cast<int>(factor_->nsuper);
  if (upper.rows() != n_ || upper.cols() != n_ || !upper.isCompressed())
    throw std::logic_error("supernodal factorisation: the matrix is not the analysed one");
  if (!part.empty() && static_cast<int>(part.size()) != n_)
    throw std::logic_error("supernodal factorisation: one part per unknown");
  super_ = static_cast<const int*>(factor_->super);
  pi_ = static_cast<const int*>(factor_->pi);
  px_ = static_cast<const int*>(factor_->px);
  rows_ = static_cast<const int*>(factor_->s);
  const int* perm = static_cast<const int*>(factor_->Perm);

  const std::vector<int>& position = tree_.position;
  const std::vector<int>& supernode_of_column = tree_.supernode_of_column;

  // Each supernode's group: a half's where all its columns are that half's unknowns. A half's
  // supernode must have only its half's supernodes below it (no edge joins the halves, so none
  // is, unless the parts are not a separator's): else everything is the separator's.
  std::vector<int> group(nsuper_, kSeparator);
  if (!part.empty())
    for (int s = 0; s < nsuper_; ++s) {
      const int g = part[perm[super_[s]]];
      bool same = g == 0 || g == 1;
      for (int k = super_[s] + 1; same && k < super_[s + 1]; ++k) same = part[perm[k]] == g;
      if (same) group[s] = g;
    }
  bool split = true;
  for (int s = 0; s < nsuper_ && split; ++s) {
    const int parent = tree_.parent[s];
    split = parent < 0 || group[parent] == group[s] || group[parent] == kSeparator;
  }
  if (!split) std::fill(group.begin(), group.end(), kSeparator);
  for (int s = 0; s < nsuper_; ++s) members_[group[s]].push_back(s);
  separator_slot_.assign(n_, -1);
  for (int s : members_[kSeparator])
    for (int k = super_[s]; k < super_[s + 1]; ++k) {
      separator_slot_[k] = static_cast<int>(separator_columns_.size());
      separator_columns_.push_back(k);
    }

  // Where each entry of the upper triangle lands in the factor's lower triangle: column
  // min(P(r), P(c)), row max(P(r), P(c)) of P A Pᵀ, found in that column's supernode.
  const auto target_of = [&](int r, int c, int& s) {
    const int j = std::min(position[r], position[c]), i = std::max(position[r], position[c]);
    s = supernode_of_column[j];
    const int width = super_[s + 1] - super_[s];
    const int height = pi_[s + 1] - pi_[s];
    int place = i - super_[s];
    if (place >= width) {
      const int* first = rows_ + pi_[s] + width;
      const int* found = std::lower_bound(first, rows_ + pi_[s] + height, i);
      if (found == rows_ + pi_[s] + height || *found != i)
        throw std::logic_error("supernodal factorisation: an entry outside the analysed pattern");
      place = width + static_cast<int>(found - first);
    }
    return (j - super_[s]) * height + place;
  };
  // Found once per entry, then sorted by supernode (a counting sort, entries in their order).
  const auto entries = static_cast<std::size_t>(upper.nonZeros());
  std::vector<int> supernode_of_entry(entries), target_of_entry(entries);
  entry_start_.assign(nsuper_ + 1, 0);
  for (int c = 0; c < n_; ++c)
    for (int p = upper.outerIndexPtr()[c]; p < upper.outerIndexPtr()[c + 1]; ++p) {
      target_of_entry[p] = target_of(upper.innerIndexPtr()[p], c, supernode_of_entry[p]);
      ++entry_start_[supernode_of_entry[p] + 1];
    }
  for (int s = 0; s < nsuper_; ++s) entry_start_[s + 1] += entry_start_[s];
  entry_source_.resize(entries);
  entry_target_.resize(entries);
  std::vector<std::size_t> next(entry_start_.begin(), entry_start_.end() - 1);
  for (std::size_t p = 0; p < entries; ++p) {
    const std::size_t k = next[supernode_of_entry[p]]++;
    entry_source_[k] = static_cast<int>(p);
    entry_target_[k] = target_of_entry[p];
  }
  next_row_.assign(nsuper_, 0);
  next_in_list_.assign(nsuper_, -1);
  for (Workspace& w : workspaces_) {
    w.position_in_supernode.resize(n_);
    w.update.resize(factor_->maxcsize);
  }
}

// Pseudocode: left-looking supernodal Cholesky (Ng and Peyton, "Block sparse Cholesky
// algorithms on advanced uniprocessor computers", SIAM J. Sci. Comput. 14, 1993; the scheme of
// CHOLMOD's cholmod_super_numeric, Chen, Davis, Hager and Rajamanickam, ACM TOMS 35, 2008):
//   for each supernode s, children first:
//     L_s ← the columns of P A Pᵀ in s
//     for each d below s whose rows meet s's columns (the lists):
//       C ← L_d[rows ≥ first of s] L_d[rows in s's columns]ᵀ      dsyrk + dgemm
//       L_s −= C, scattered by row;  link d to the next supernode its rows meet
//     L_ss ← chol(L_ss);  L_rest ← L_rest L_ss⁻ᵀ                  dpotrf, dtrsm
//     link s to the supernode of its first row below
// The halves' supernodes only ever meet their own half's and the separator's, so each half
// runs on its own thread with its own lists; the separator's then take the updates of both.
void SupernodalFactorization::factorize(const SparseMatrix& upper, bool two_threads) {
  if (upper.rows() != n_ || !upper.isCompressed() ||
      static_cast<std::size_t>(upper.nonZeros()) != entry_source_.size())
    throw std::logic_error("supernodal factorisation: the matrix is not the analysed one");
  single_.reset();  // before the double values are made again: not both at once
  if (factor_->xtype == CHOLMOD_PATTERN &&
      !cholmod_change_factor(CHOLMOD_REAL, true, true, true, true, factor_, common_))
    throw std::runtime_error("supernodal factorisation: CHOLMOD could not allocate the factor");
  for (auto& head : head_) head.assign(nsuper_, -1);
  std::array<Workspace, 2>& work = workspaces_;
  for (Workspace& w : work) {
    w.values = upper.valuePtr();
    w.failed_column = -1;
  }
  // Each half on its thread, or both on one where the runtime grants one (the same values).
  numerics::run_two_parts(halves_in_parallel(two_threads), [&](int half) { factor_group(half, work[half]); });
  int failed = -1;
  for (const Workspace& w : work)
    if (w.failed_column >= 0 && (failed < 0 || w.failed_column < failed)) failed = w.failed_column;
  if (failed < 0) {
    factor_group(kSeparator, work[0]);
    failed = work[0].failed_column;
  }
  if (failed >= 0) {
    factor_->minor = static_cast<std::size_t>(failed);
    throw SingularSystem("the flow matrix is not positive definite (pivot " + std::to_string(failed) + ")");
  }
  factor_->minor = factor_->n;
  factor_->is_ll = true;
}

bool SupernodalFactorization::halves_in_parallel(bool two_threads) const {
  return two_threads && !members_[0].empty() && !members_[1].empty() && blas_is_thread_safe();
}

void SupernodalFactorization::factor_group(int group, Workspace& work) {
  std::vector<int>* lists[3] = {&head_[group], nullptr, nullptr};
  std::size_t list_count = 1;
  if (group == kSeparator) {  // the halves' lists end here too
    lists[0] = &head_[0];
    lists[1] = &head_[1];
    lists[2] = &head_[kSeparator];
    list_count = 3;
  }
  for (int s : members_[group]) {
    factor_supernode(s, std::span<std::vector<int>* const>(lists, list_count), head_[group], work);
    if (work.failed_column >= 0) return;
  }
}

void SupernodalFactorization::factor_supernode(int s, std::span<std::vector<int>* const> lists,
                                               std::vector<int>& relink, Workspace& work) {
  static constexpr double one = 1.0, zero = 0.0;
  double* const x = static_cast<double*>(factor_->x);
  const int first = super_[s], width = super_[s + 1] - first;
  const int row_begin = pi_[s], height = pi_[s + 1] - row_begin;
  double* const ls = x + px_[s];
  for (int i = 0; i < height; ++i) work.position_in_supernode[rows_[row_begin + i]] = i;
  std::fill(ls, ls + static_cast<std::size_t>(height) * width, 0.0);
  for (std::size_t k = entry_start_[s]; k < entry_start_[s + 1]; ++k) ls[entry_target_[k]] = work.values[entry_source_[k]];

  for (std::vector<int>* list : lists) {
    int d = (*list)[s];
    (*list)[s] = -1;
    while (d >= 0) {
      const int following = next_in_list_[d];
      const int d_width = super_[d + 1] - super_[d];
      const int d_begin = pi_[d], d_end = pi_[d + 1], d_height = d_end - d_begin;
      const int meet = d_begin + next_row_[d];  // d's first row in s
      int past = meet;                           // d's first row below s's columns
      while (past < d_end && rows_[past] < first + width) ++past;
      const int inside = past - meet, below = d_end - meet;
      const double* ld = x + px_[d] + (meet - d_begin);
      double* c = work.update.data();
      const int rest = below - inside;
      {
        const std::unique_lock<std::mutex> blas = hold_blas();
        dsyrk_("L", "N", &inside, &d_width, &one, ld, &d_height, &zero, c, &below);
        if (rest > 0)
          dgemm_("N", "T", &rest, &inside, &d_width, &one, ld + inside, &d_height, ld, &d_height, &zero, c + inside,
                 &below);
      }
      for (int j = 0; j < inside; ++j) {
        double* column = ls + static_cast<std::size_t>(rows_[meet + j] - first) * height;
        const double* cj = c + static_cast<std::size_t>(j) * below;
        for (int i = j; i < below; ++i) column[work.position_in_supernode[rows_[meet + i]]] -= cj[i];
      }
      next_row_[d] = past - d_begin;
      if (past < d_end) {
        const int t = tree_.supernode_of_column[rows_[past]];
        next_in_list_[d] = relink[t];
        relink[t] = d;
      }
      d = following;
    }
  }

  const std::unique_lock<std::mutex> blas = hold_blas();
  int info = 0;
  dpotrf_("L", &width, ls, &height, &info);
  if (info != 0) {
    work.failed_column = first + info - 1;
    return;
  }
  if (height > width) {
    const int rest = height - width;
    dtrsm_("R", "L", "T", "N", &rest, &width, &one, ls, &height, ls + width, &height);
    next_row_[s] = width;
    const int t = tree_.supernode_of_column[rows_[row_begin + width]];
    next_in_list_[s] = relink[t];
    relink[t] = s;
  }
}

}  // namespace hydrodda::numerics

namespace hydrodda::numerics {
namespace {

// Σ a_i b_i in four running sums, which the compiler can keep in vector registers side by
// side; one sum waits on its last addition at every term (the backward solve ran 1.35 times
// as long as the forward one, whose updates are independent).
template <typename Value>
double dot(const Value* a, const double* b, int n) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += static_cast<double>(a[i]) * b[i];
    s1 += static_cast<double>(a[i + 1]) * b[i + 1];
    s2 += static_cast<double>(a[i + 2]) * b[i + 2];
    s3 += static_cast<double>(a[i + 3]) * b[i + 3];
  }
  for (; i < n; ++i) s0 += static_cast<double>(a[i]) * b[i];
  return (s0 + s1) + (s2 + s3);
}

}  // namespace

// Pseudocode (the supernodal triangular solves; written out since they touch no BLAS):
//   forward, children first:  y_s ← L_ss⁻¹ y_s;  y_r −= L_rs y_s for the rows r below
//   backward, parents first:  y_s ← L_ss⁻ᵀ (y_s − L_rsᵀ y_r)
// A half's rows below lie in its half or the separator: each half sums its terms on the
// separator apart, and the separator's rows take both sums, the first half's first.
Eigen::VectorXd SupernodalFactorization::solve(const Eigen::VectorXd& b, bool two_threads) const {
  Eigen::VectorXd x = b;
  solve_forward(x, two_threads);
  solve_backward(x, two_threads);
  return x;
}

void SupernodalFactorization::solve_forward(Eigen::VectorXd& v, bool two_threads) const {
  if (single_) solve_forward_with(single_.get(), v, two_threads);
  else solve_forward_with(static_cast<const double*>(factor_->x), v, two_threads);
}

void SupernodalFactorization::solve_backward(Eigen::VectorXd& v, bool two_threads) const {
  if (single_) solve_backward_with(single_.get(), v, two_threads);
  else solve_backward_with(static_cast<const double*>(factor_->x), v, two_threads);
}

template <typename Value>
void SupernodalFactorization::solve_forward_with(const Value* l, Eigen::VectorXd& v, bool two_threads) const {
  if (v.size() != n_) throw std::logic_error("supernodal solve: the right-hand side has the wrong size");
  if (!l) throw std::logic_error("supernodal solve: nothing factored");
  const int* perm = static_cast<const int*>(factor_->Perm);
  Eigen::VectorXd y(n_);
  for (int k = 0; k < n_; ++k) y[k] = v[perm[k]];
  for (std::vector<double>& sums : separator_sums_) sums.assign(separator_columns_.size(), 0.0);
  numerics::run_two_parts(halves_in_parallel(two_threads),
                          [&](int half) { forward_over(half, l, y.data(), separator_sums_[half].data()); });
  for (std::size_t t = 0; t < separator_columns_.size(); ++t)
    y[separator_columns_[t]] -= separator_sums_[0][t] + separator_sums_[1][t];
  forward_over(kSeparator, l, y.data(), nullptr);
  v = std::move(y);
}

template <typename Value>
void SupernodalFactorization::solve_backward_with(const Value* l, Eigen::VectorXd& v, bool two_threads) const {
  if (v.size() != n_) throw std::logic_error("supernodal solve: the right-hand side has the wrong size");
  if (!l) throw std::logic_error("supernodal solve: nothing factored");
  backward_over(kSeparator, l, v.data());
  numerics::run_two_parts(halves_in_parallel(two_threads), [&](int half) { backward_over(half, l, v.data()); });
  const int* perm = static_cast<const int*>(factor_->Perm);
  Eigen::VectorXd x(n_);
  for (int k = 0; k < n_; ++k) x[perm[k]] = v[k];
  v = std::move(x);
}

template <typename Value>
void SupernodalFactorization::forward_over(int group, const Value* const x, double* y, double* separator) const {
  std::vector<double> below;
  for (int s : members_[group]) {
    const int first = super_[s], width = super_[s + 1] - first;
    const int* rows = rows_ + pi_[s];
    const int height = pi_[s + 1] - pi_[s];
    const Value* l = x + px_[s];
    double* ys = y + first;
    for (int j = 0; j < width; ++j) {
      const Value* column = l + static_cast<std::size_t>(j) * height;
      const double v = ys[j] /= static_cast<double>(column[j]);
      for (int i = j + 1; i < width; ++i) ys[i] -= static_cast<double>(column[i]) * v;
    }
    below.assign(height - width, 0.0);
    for (int j = 0; j < width; ++j) {
      const Value* column = l + static_cast<std::size_t>(j) * height + width;
      const double v = ys[j];
      for (int i = 0; i < height - width; ++i) below[i] += static_cast<double>(column[i]) * v;
    }
    for (int i = 0; i < height - width; ++i) {
      const int r = rows[width + i];
      const int slot = separator_slot_[r];
      if (separator && slot >= 0) separator[slot] += below[i];  // subtracted from y later
      else y[r] -= below[i];
    }
  }
}

template <typename Value>
void SupernodalFactorization::backward_over(int group, const Value* const x, double* y) const {
  std::vector<double> below;
  for (auto it = members_[group].rbegin(); it != members_[group].rend(); ++it) {
    const int s = *it;
    const int first = super_[s], width = super_[s + 1] - first;
    const int* rows = rows_ + pi_[s];
    const int height = pi_[s + 1] - pi_[s];
    const Value* l = x + px_[s];
    double* ys = y + first;
    below.resize(height - width);
    for (int i = 0; i < height - width; ++i) below[i] = y[rows[width + i]];
    for (int j = 0; j < width; ++j)
      ys[j] -= dot(l + static_cast<std::size_t>(j) * height + width, below.data(), height - width);
    for (int j = width - 1; j >= 0; --j) {
      const Value* column = l + static_cast<std::size_t>(j) * height;
      ys[j] = (ys[j] - dot(column + j + 1, ys + j + 1, width - j - 1)) / static_cast<double>(column[j]);
    }
  }
}

// Rounds each value to the nearest float in place, over the first half of the double values'
// own memory, then shrinks that block to the floats (CHOLMOD's realloc; the C library's
// mremap hands the rest back at once), so that the two never stand side by side (another
// 130 MB at 10^6 triangles). The block is then this object's, CHOLMOD's factor symbolic.
// In chunks: a chunk's doubles are all read into a buffer before its floats are written,
// and its floats cover only doubles of this chunk or of earlier ones (float k lies in the
// bytes of double k / 2). Where a diagonal entry would leave float's range (a conductivity
// beyond 1e±76 in the matrix's units), the factor stays in double.
void SupernodalFactorization::keep_in_single_precision() {
  if (single_) return;
  if (factor_->xtype != CHOLMOD_REAL || !factor_->x || factor_->minor != factor_->n)
    throw std::logic_error("supernodal factorisation: nothing factored to keep");
  const double* const x = static_cast<const double*>(factor_->x);
  for (int s = 0; s < nsuper_; ++s) {
    const int width = super_[s + 1] - super_[s], height = pi_[s + 1] - pi_[s];
    for (int j = 0; j < width; ++j) {
      const auto d = static_cast<float>(x[px_[s] + static_cast<std::size_t>(j) * height + j]);
      if (!(d >= std::numeric_limits<float>::min() && d <= std::numeric_limits<float>::max())) return;
    }
  }
  const std::size_t size = factor_->xsize;
  auto* const bytes = static_cast<unsigned char*>(factor_->x);
  constexpr std::size_t kChunk = 1 << 14;
  std::vector<float> chunk(kChunk);
  for (std::size_t first = 0; first < size; first += kChunk) {
    const std::size_t count = std::min(kChunk, size - first);
    for (std::size_t k = 0; k < count; ++k) {
      double value;
      std::memcpy(&value, bytes + (first + k) * sizeof(double), sizeof(double));
      chunk[k] = static_cast<float>(value);
    }
    std::memcpy(bytes + first * sizeof(float), chunk.data(), count * sizeof(float));
  }
  std::size_t doubles = size;
  void* kept = cholmod_realloc((size + 1) / 2, sizeof(double), factor_->x, &doubles, common_);
  if (!kept) throw std::runtime_error("supernodal factorisation: CHOLMOD could not shrink the factor's values");
  // CHOLMOD's own numeric-to-symbolic change, but for the values, which are kept here.
  factor_->x = nullptr;
  factor_->xtype = CHOLMOD_PATTERN;
  single_ = std::unique_ptr<float[], CholmodValues>(static_cast<float*>(kept), CholmodValues{common_, doubles});
}

void CholmodValues::operator()(float* values) const {
  cholmod_free(doubles, sizeof(double), values, common);
}

}  // namespace hydrodda::numerics
