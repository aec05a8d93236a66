#include "dda/block_cholesky.hpp"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <Eigen/Cholesky>

#include "dda/array_growth.hpp"
#include "numerics/parallel.hpp"

namespace hydrodda::dda {

namespace {

// One entry of row k of the permuted lower triangle: column j < k, and where its block comes
// from: a block of the matrix (`source` its pair), transposed if the permutation swapped its
// row and column, or a spring w wᵀ joining the two blocks (`source` the spring), whose part
// in A(k, j) is w_row w_columnᵀ (`transposed`: the row's block is the spring's block_b).
struct RowEntry {
  int column;
  int source;
  bool transposed;
  bool spring;
};


// x[rows[q]] −= l values[q]ᵀ for q < count: the update of row k by one earlier column, the
// factorisation's inner loop. Portable in Eigen; by hand with AVX2 and FMA where the CPU has
// them (chosen once; bench_dda, BM_WallGraphFactorise), as the solves below.
void subtract_products_portable(const Matrix6& l, const Matrix6* values, const int* rows, int count,
                                Matrix6* x) {
  for (int q = 0; q < count; ++q) x[rows[q]].noalias() -= l * values[q].transpose();
}

#if defined(__x86_64__)
// Column c of l vᵀ is Σ_j l(:, j) v(c, j): the columns of l held in registers (a 4-wide and a
// 2-wide part each), v's entries broadcast.
[[gnu::target("avx2,fma")]] void subtract_products_avx2(const Matrix6& l, const Matrix6* values, const int* rows,
                                                       int count, Matrix6* x) {
  __m256d l_head[6];
  __m128d l_tail[6];
  for (int j = 0; j < 6; ++j) {
    l_head[j] = _mm256_loadu_pd(l.data() + 6 * j);
    l_tail[j] = _mm_loadu_pd(l.data() + 6 * j + 4);
  }
  for (int q = 0; q < count; ++q) {
    const double* v = values[q].data();
    double* target = x[rows[q]].data();
    for (int c = 0; c < 6; ++c) {
      __m256d head = _mm256_loadu_pd(target + 6 * c);
      __m128d tail = _mm_loadu_pd(target + 6 * c + 4);
      for (int j = 0; j < 6; ++j) {
        const __m256d b = _mm256_broadcast_sd(v + 6 * j + c);
        head = _mm256_fnmadd_pd(l_head[j], b, head);
        tail = _mm_fnmadd_pd(l_tail[j], _mm256_castpd256_pd128(b), tail);
      }
      _mm256_storeu_pd(target + 6 * c, head);
      _mm_storeu_pd(target + 6 * c + 4, tail);
    }
  }
}
#endif

#if defined(__x86_64__)
// The two 6×6 products of a column's elimination (eliminate_columns), with AVX2 where the CPU
// has it. Each entry is summed as Eigen's coefficient-based product (the portable form) sums
// it: Σ_k a(r, k) b(k, c), k ascending, a product and then an addition each (no fused
// multiply–add), so that both forms give the same entries to the bit.
//
// x b for b = mᵀ: column c is Σ_k x(:, k) m(c, k).
[[gnu::target("avx2")]] void multiply_by_transpose_avx2(const Matrix6& x, const Matrix6& m, Matrix6& out) {
  const double* xs = x.data();
  for (int c = 0; c < 6; ++c) {
    __m256d head = _mm256_mul_pd(_mm256_loadu_pd(xs), _mm256_set1_pd(m(c, 0)));
    __m128d tail = _mm_mul_pd(_mm_loadu_pd(xs + 4), _mm_set1_pd(m(c, 0)));
    for (int k = 1; k < 6; ++k) {
      head = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(xs + 6 * k), _mm256_set1_pd(m(c, k))), head);
      tail = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(xs + 6 * k + 4), _mm_set1_pd(m(c, k))), tail);
    }
    _mm256_storeu_pd(out.data() + 6 * c, head);
    _mm_storeu_pd(out.data() + 6 * c + 4, tail);
  }
}

// Rows r … r + 3 of column c of d −= l lᵀ: Σ_k l(r, k) l(c, k).
[[gnu::target("avx2")]] inline void subtract_gram_four_avx2(const Matrix6& l, int c, int r, Matrix6& d) {
  const double* ls = l.data();
  __m256d sum = _mm256_mul_pd(_mm256_loadu_pd(ls + r), _mm256_set1_pd(l(c, 0)));
  for (int k = 1; k < 6; ++k)
    sum = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(ls + 6 * k + r), _mm256_set1_pd(l(c, k))), sum);
  double* target = d.data() + 6 * c + r;
  _mm256_storeu_pd(target, _mm256_sub_pd(_mm256_loadu_pd(target), sum));
}

// Rows r, r + 1 of column c of the same.
[[gnu::target("avx2")]] inline void subtract_gram_two_avx2(const Matrix6& l, int c, int r, Matrix6& d) {
  const double* ls = l.data();
  __m128d sum = _mm_mul_pd(_mm_loadu_pd(ls + r), _mm_set1_pd(l(c, 0)));
  for (int k = 1; k < 6; ++k) sum = _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(ls + 6 * k + r), _mm_set1_pd(l(c, k))), sum);
  double* target = d.data() + 6 * c + r;
  _mm_storeu_pd(target, _mm_sub_pd(_mm_loadu_pd(target), sum));
}

// d −= l lᵀ on d's lower triangle (and a few entries above it, in whole registers): the pivot
// block goes only to Eigen's LLT, which reads no other.
[[gnu::target("avx2")]] void subtract_gram_lower_avx2(const Matrix6& l, Matrix6& d) {
  subtract_gram_four_avx2(l, 0, 0, d);
  subtract_gram_two_avx2(l, 0, 4, d);
  subtract_gram_four_avx2(l, 1, 0, d);
  subtract_gram_two_avx2(l, 1, 4, d);
  subtract_gram_four_avx2(l, 2, 2, d);
  subtract_gram_four_avx2(l, 3, 2, d);
  subtract_gram_two_avx2(l, 4, 4, d);
  subtract_gram_two_avx2(l, 5, 4, d);
}
#endif

bool cpu_has_avx2_fma() {
#if defined(__x86_64__)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

// Whether the AVX2/FMA kernels are in use: decided when the program starts.
bool vectorised = cpu_has_avx2_fma();

void subtract_products(const Matrix6& l, const Matrix6* values, const int* rows, int count, Matrix6* x) {
#if defined(__x86_64__)
  if (vectorised) return subtract_products_avx2(l, values, rows, count, x);
#endif
  subtract_products_portable(l, values, rows, count, x);
}

// L(k, i) = X_i L(i, i)⁻ᵀ.
Matrix6 multiply_by_transpose(const Matrix6& x, const Matrix6& m) {
#if defined(__x86_64__)
  if (vectorised) {
    Matrix6 out;
    multiply_by_transpose_avx2(x, m, out);
    return out;
  }
#endif
  return x * m.transpose();
}

// The pivot's d −= L(k, i) L(k, i)ᵀ, on its lower triangle at least.
void subtract_gram_lower(const Matrix6& l, Matrix6& d) {
#if defined(__x86_64__)
  if (vectorised) return subtract_gram_lower_avx2(l, d);
#endif
  d.noalias() -= l * l.transpose();
}

}  // namespace

// Its memory goes too: a coupled run lets go of the factor between passes, while the flow
// model factors (100 MB for the 340,000 off-diagonal blocks of a 10,200-block seal whose
// joints are closed).
void BlockCholesky::clear() { *this = BlockCholesky(); }

bool BlockCholesky::use_vectorised_kernels(bool on) {
  vectorised = on && cpu_has_avx2_fma();
  return vectorised;
}

namespace {

// The permuted strictly lower triangle of A + Σ w wᵀ by rows, and the springs on each block's
// diagonal.
struct LowerRows {
  std::vector<int> start;  // row k: entries[start[k] … start[k + 1])
  std::vector<RowEntry> entries;
  std::vector<int> touching_start;  // the springs touching block b: touching[touching_start[b] …]
  std::vector<int> touching;
};

// Both by counting sort: the matrix's blocks off the diagonal, and one entry for each spring
// joining two blocks (a pair of blocks that several springs join has an entry for each: the
// row sums them, and the pattern is the same); the springs that touch each block.
LowerRows gather_lower_rows(const BlockMatrix& a, const RankOneTerms& springs, const std::vector<int>& position) {
  const int n = a.block_count;
  LowerRows l;
  l.start.assign(n + 1, 0);
  for (auto [col, row] : a.pairs) ++l.start[std::max(position[col], position[row]) + 1];
  for (const RankOneTerm& t : springs)
    if (t.joins_two_blocks()) ++l.start[std::max(position[t.block_a], position[t.block_b]) + 1];
  for (int k = 0; k < n; ++k) l.start[k + 1] += l.start[k];
  l.entries.resize(l.start[n]);
  l.touching_start.assign(n + 1, 0);
  for (const RankOneTerm& t : springs) {
    if (t.block_a >= 0) ++l.touching_start[t.block_a + 1];
    if (t.block_b >= 0 && t.block_b != t.block_a) ++l.touching_start[t.block_b + 1];
  }
  for (int b = 0; b < n; ++b) l.touching_start[b + 1] += l.touching_start[b];
  l.touching.resize(l.touching_start[n]);

  std::vector<int> next(l.start.begin(), l.start.end() - 1);
  for (std::size_t p = 0; p < a.pairs.size(); ++p) {
    const int pc = position[a.pairs[p].first], pr = position[a.pairs[p].second];
    // off[p] is A(row, column): it is A'(pr, pc) as stored, or its transpose if pc > pr.
    if (pr > pc)
      l.entries[next[pr]++] = {pc, static_cast<int>(p), false, false};
    else
      l.entries[next[pc]++] = {pr, static_cast<int>(p), true, false};
  }
  std::vector<int> next_touching(l.touching_start.begin(), l.touching_start.end() - 1);
  for (std::size_t q = 0; q < springs.size(); ++q) {
    const RankOneTerm& t = springs[q];
    const int spring = static_cast<int>(q);
    if (t.block_a >= 0) l.touching[next_touching[t.block_a]++] = spring;
    if (t.block_b >= 0 && t.block_b != t.block_a) l.touching[next_touching[t.block_b]++] = spring;
    if (!t.joins_two_blocks()) continue;
    const int pa = position[t.block_a], pb = position[t.block_b];
    if (pa > pb)
      l.entries[next[pa]++] = {pb, spring, false, true};
    else
      l.entries[next[pb]++] = {pa, spring, true, true};
  }
  return l;
}

// The elimination tree, in elimination positions: Liu's algorithm with path compression
// through `ancestor` (Davis 2006, §4.1, cs_etree). −1 at a root.
std::vector<int> find_elimination_tree(const LowerRows& l) {
  const int n = static_cast<int>(l.start.size()) - 1;
  std::vector<int> parent(n, -1);
  std::vector<int> ancestor(n, -1);
  for (int k = 0; k < n; ++k)
    for (int e = l.start[k]; e < l.start[k + 1]; ++e)
      for (int i = l.entries[e].column; i != -1 && i < k;) {
        const int next = ancestor[i];
        ancestor[i] = k;
        if (next == -1) parent[i] = k;
        i = next;
      }
  return parent;
}

// ereach(k) (Davis 2006, §4.2, cs_ereach): the row pattern of L(k, :), on stack[top … n−1],
// children first: the walk from each entry's column up the tree to the first node already on
// the stack. `start` maps the column to where the walk begins (−1: not at all) and `keep` says
// which nodes it may pass. Each part of the tree, and the top, walks with its own Reach.
struct Reach {
  std::vector<int> mark, stack, path;
  explicit Reach(int n) : mark(n, -1), stack(n), path(n) {}
  template <class Start, class Keep>
  int walk(int k, const LowerRows& l, const std::vector<int>& parent, Start start, Keep keep) {
    const int n = static_cast<int>(mark.size());
    int top = n;
    mark[k] = k;
    for (int e = l.start[k]; e < l.start[k + 1]; ++e) {
      int length = 0;
      for (int i = start(l.entries[e].column); i >= 0 && keep(i) && mark[i] != k; i = parent[i]) {
        path[length++] = i;
        mark[i] = k;
      }
      while (length > 0) stack[--top] = path[--length];
    }
    return top;
  }
};

constexpr auto from_column = [](int c) { return c; };
constexpr auto anywhere = [](int) { return true; };

// L's block column starts: column i holds a block for each row k whose ereach(k) passes i.
std::vector<int> count_columns(const LowerRows& l, const std::vector<int>& parent) {
  const int n = static_cast<int>(parent.size());
  Reach reach(n);
  std::vector<int> column_start(n + 1, 0);
  for (int k = 0; k < n; ++k)
    for (int top = reach.walk(k, l, parent, from_column, anywhere); top < n; ++top)
      ++column_start[reach.stack[top] + 1];
  for (int k = 0; k < n; ++k) column_start[k + 1] += column_start[k];
  return column_start;
}

// Where row t of a lower triangle of blocks stored row by row begins: the t (t + 1) / 2 blocks
// of the rows before it.
std::size_t triangle_start(std::size_t t) { return t * (t + 1) / 2; }

}  // namespace

// The numeric factorisation of one matrix into the factor's allocated columns: its rows,
// pivots and working arrays while it runs.
//
// The top's rows take most of the arithmetic (a separator's row reaches deep into both
// parts), so they are done in two phases. In the first (eliminate_parts), side by side, each
// part eliminates its own columns from its own rows and then from every top row, in the top's
// order: row k of the top restricted to part p is a triangular solve with part p's columns
// alone (they hold rows of part p and of the top only), and the part's columns receive their
// rows in the top as the sequential order would give them. What this leaves on the top's
// columns of row k, and on its pivot, waits in top_sums_[p] (block (k, j) of the top at
// triangle_start(k) + j, the pivot at triangle_start(k) + k). In the second (eliminate_top),
// row by row, the top's own columns are eliminated from the row the two sums and A's own
// entries make. The arithmetic is the same on one thread or two.
class BlockCholesky::Elimination {
 public:
  Elimination(BlockCholesky& factor, const BlockMatrix& a, const RankOneTerms& springs, const std::vector<int>& order,
              const LowerRows& rows);
  // Phase one; false if a part's pivot is not positive definite.
  bool eliminate_parts();
  // Phase two; false if a pivot of the top is not positive definite.
  bool eliminate_top();

 private:
  BlockCholesky& l_;
  const BlockMatrix& a_;
  const RankOneTerms& springs_;
  const std::vector<int>& order_;
  const LowerRows& rows_;
  const int n_;
  std::vector<signed char> part_of_;       // by position: 0 or 1 (a part) or 2 (the top)
  std::vector<int> top_above_;             // where a part's node first meets the top (−1: never)
  std::vector<int> filled_;                // per column of L: its next free block
  std::array<Reach, 3> reaches_;           // part 0, part 1, the top
  std::array<Matrix6Array, 2> row_work_;   // the row being eliminated, per part, by position
  std::array<Matrix6Array, 2> top_sums_;   // each part's share of the top's rows

  bool eliminate_part_columns(int p);
  void eliminate_part_from_top_rows(int p);
  template <class Take>
  void scatter_row(int k, Matrix6Array& x, Take take) const;
  Matrix6 diagonal(int k) const;
  void eliminate_columns(int k, const Reach& r, int top, Matrix6Array& x, Matrix6& d);
  bool factor_pivot(int k, const Matrix6& d);
};

BlockCholesky::Elimination::Elimination(BlockCholesky& factor, const BlockMatrix& a, const RankOneTerms& springs,
                                        const std::vector<int>& order, const LowerRows& rows)
    : l_(factor),
      a_(a),
      springs_(springs),
      order_(order),
      rows_(rows),
      n_(factor.block_count_),
      part_of_(n_),
      top_above_(n_, -1),
      filled_(factor.column_start_.begin(), factor.column_start_.end() - 1),
      reaches_{Reach(n_), Reach(n_), Reach(n_)} {
  for (int p = 0; p < 3; ++p)
    for (int k : l_.part_columns_[p]) part_of_[k] = static_cast<signed char>(p);
  for (int k = n_ - 1; k >= 0; --k)
    if (part_of_[k] != 2 && l_.parent_[k] >= 0)
      top_above_[k] = part_of_[l_.parent_[k]] == 2 ? l_.parent_[k] : top_above_[l_.parent_[k]];
  resize_for_overwrite(l_.row_, l_.column_start_[n_]);
  resize_for_overwrite(l_.value_, l_.column_start_[n_]);
  l_.inverse_diagonal_.resize(n_);
  // Each part works its row in its own array; the top's rows use part 0's.
  for (Matrix6Array& x : row_work_) x.assign(n_, Matrix6::Zero());
  for (Matrix6Array& sums : top_sums_) resize_for_overwrite(sums, triangle_start(l_.part_columns_[2].size()));
}

// Row k's entries A(k, c) for the columns c that `take` accepts, added into x (zero there).
template <class Take>
void BlockCholesky::Elimination::scatter_row(int k, Matrix6Array& x, Take take) const {
  for (int e = rows_.start[k]; e < rows_.start[k + 1]; ++e) {
    const RowEntry& entry = rows_.entries[e];
    if (!take(entry.column)) continue;
    Matrix6& target = x[entry.column];
    if (entry.spring) {
      const RankOneTerm& t = springs_[entry.source];
      if (entry.transposed)
        target.noalias() += t.w_b * t.w_a.transpose();
      else
        target.noalias() += t.w_a * t.w_b.transpose();
    } else if (entry.transposed) {
      target += a_.off[entry.source].transpose();
    } else {
      target += a_.off[entry.source];
    }
  }
}

// A(k, k): the matrix's diagonal block and the springs on it.
Matrix6 BlockCholesky::Elimination::diagonal(int k) const {
  const int b = order_[k];
  Matrix6 d = a_.diagonal[b];
  for (int q = rows_.touching_start[b]; q < rows_.touching_start[b + 1]; ++q) {
    const Vector6 w = springs_[rows_.touching[q]].part_on(b);
    d.noalias() += w * w.transpose();
  }
  return d;
}

// The columns i = stack[top … n−1] in turn: L(k, i) from x_i, then row k updated by column i
// (x_r −= L(k, i) L(r, i)ᵀ), and d −= L(k, i) L(k, i)ᵀ.
void BlockCholesky::Elimination::eliminate_columns(int k, const Reach& r, int top, Matrix6Array& x, Matrix6& d) {
  for (int s = top; s < n_; ++s) {
    const int i = r.stack[s];
    const Matrix6 lki = multiply_by_transpose(x[i], l_.inverse_diagonal_[i]);
    x[i].setZero();
    const int first = l_.column_start_[i];
    subtract_products(lki, l_.value_.data() + first, l_.row_.data() + first, filled_[i] - first, x.data());
    subtract_gram_lower(lki, d);
    l_.row_[filled_[i]] = k;
    l_.value_[filled_[i]++] = lki;
  }
}

// L(k, k) ← chol(d), kept as its inverse; false if d is not positive definite.
bool BlockCholesky::Elimination::factor_pivot(int k, const Matrix6& d) {
  const Eigen::LLT<Matrix6> llt(d);
  if (llt.info() != Eigen::Success || !std::isfinite(d.trace())) return false;
  l_.inverse_diagonal_[k] = llt.matrixL().solve(Matrix6::Identity());
  return true;
}

// Part p's own rows, whole: they reach only part p's columns.
bool BlockCholesky::Elimination::eliminate_part_columns(int p) {
  Matrix6Array& x = row_work_[p];
  Reach& r = reaches_[p];
  for (int k : l_.part_columns_[p]) {
    scatter_row(k, x, anywhere);
    Matrix6 d = diagonal(k);
    eliminate_columns(k, r, r.walk(k, rows_, l_.parent_, from_column, anywhere), x, d);
    if (!factor_pivot(k, d)) return false;
  }
  return true;
}

// Part p's columns eliminated from every top row; what is left on the top's columns and
// pivot goes to top_sums_[p].
void BlockCholesky::Elimination::eliminate_part_from_top_rows(int p) {
  Matrix6Array& x = row_work_[p];
  Reach& r = reaches_[p];
  const std::vector<int>& top_nodes = l_.part_columns_[2];
  const auto in_part = [&](int c) { return part_of_[c] == p; };
  const auto only_in_part = [&](int c) { return in_part(c) ? c : -1; };
  for (std::size_t t = 0; t < top_nodes.size(); ++t) {
    const int k = top_nodes[t];
    scatter_row(k, x, in_part);
    Matrix6 d = Matrix6::Zero();
    eliminate_columns(k, r, r.walk(k, rows_, l_.parent_, only_in_part, in_part), x, d);
    Matrix6* sums = top_sums_[p].data() + triangle_start(t);
    for (std::size_t u = 0; u < t; ++u) {
      Matrix6& xj = x[top_nodes[u]];
      sums[u] = xj;
      xj.setZero();
    }
    sums[t] = d;
  }
}

bool BlockCholesky::Elimination::eliminate_parts() {
  std::array<bool, 2> part_ok{true, true};
  numerics::run_two_parts(l_.run_parts_in_parallel(), [&](int p) {
    part_ok[p] = eliminate_part_columns(p);
    if (part_ok[p]) eliminate_part_from_top_rows(p);
  });
  return part_ok[0] && part_ok[1];
}

bool BlockCholesky::Elimination::eliminate_top() {
  const std::vector<int>& top_nodes = l_.part_columns_[2];
  Matrix6Array& x = row_work_[0];
  Reach& r = reaches_[2];
  const auto in_top = [&](int c) { return part_of_[c] == 2; };
  const auto top_of = [&](int c) { return part_of_[c] == 2 ? c : top_above_[c]; };
  for (std::size_t t = 0; t < top_nodes.size(); ++t) {
    const int k = top_nodes[t];
    scatter_row(k, x, in_top);
    const Matrix6* sums_0 = top_sums_[0].data() + triangle_start(t);
    const Matrix6* sums_1 = top_sums_[1].data() + triangle_start(t);
    for (std::size_t u = 0; u < t; ++u) {
      Matrix6& xj = x[top_nodes[u]];
      xj += sums_0[u];
      xj += sums_1[u];
    }
    Matrix6 d = diagonal(k);
    d += sums_0[t];
    d += sums_1[t];
    eliminate_columns(k, r, r.walk(k, rows_, l_.parent_, top_of, anywhere), x, d);
    if (!factor_pivot(k, d)) return false;
  }
  return true;
}

// Up-looking (row by row) Cholesky over blocks; Davis, "Direct Methods for Sparse Linear
// Systems" (SIAM 2006), §4.1 (elimination tree), §4.2 (row patterns by ereach), §4.8 (cs_chol),
// with every scalar become a 6×6 block:
//   parent ← etree(A);  column counts ← for each row k, the nodes ereach(k) reaches
//   split the tree into two parts and their top (split_elimination_tree)
//   for k = 0 … n−1 (each part's rows side by side, then the top's; Elimination):
//     X_j ← A(k, j) for j < k;  D ← A(k, k)
//     for i in ereach(k), children before parents:
//       L(k, i) ← X_i L(i, i)⁻ᵀ;  X_r −= L(k, i) L(r, i)ᵀ for the rows r < k of column i
//       D −= L(k, i) L(k, i)ᵀ
//     L(k, k) ← chol(D)   (fails if D is not positive definite)
bool BlockCholesky::factorise(const BlockMatrix& a, const std::vector<int>& order) {
  return factorise(a, RankOneTerms{}, order);
}

bool BlockCholesky::factorise(const BlockMatrix& a, const RankOneTerms& springs, const std::vector<int>& order) {
  // Every array below is written afresh; a factor made before keeps its memory for them, as
  // the open–close passes factor the same pattern again and again (fresh memory each time is
  // pages the kernel clears first).
  block_count_ = 0;
  const int n = a.block_count;
  position_.resize(n);
  for (int k = 0; k < n; ++k) position_[order[k]] = k;
  const LowerRows rows = gather_lower_rows(a, springs, position_);
  parent_ = find_elimination_tree(rows);
  column_start_ = count_columns(rows, parent_);
  block_count_ = n;
  split_elimination_tree();
  Elimination elimination(*this, a, springs, order, rows);
  if (!elimination.eliminate_parts() || !elimination.eliminate_top()) {
    clear();
    return false;
  }
  prepare_sweeps(order);
  return true;
}

// Where each part's columns reach the top: the forward sweep's updates beyond it wait in the
// part's own buffer. A column's rows are its ancestors ascending, its own subtree's first.
void BlockCholesky::prepare_sweeps(const std::vector<int>& order) {
  const int n = block_count_;
  top_rows_start_.resize(n);
  for (int k = 0; k < n; ++k) {
    int q = column_start_[k];
    if (top_index_[k] >= 0) {
      q = column_start_[k + 1];  // the top's own columns update the top directly
    } else {
      while (q < column_start_[k + 1] && top_index_[row_[q]] < 0) ++q;
    }
    top_rows_start_[k] = q;
  }
  for (Eigen::VectorXd& updates : top_updates_) updates.setZero(6 * static_cast<Eigen::Index>(part_columns_[2].size()));
  order_ = order;
  path_work_.setZero(6 * n);
  on_path_.assign(n, 0);
}

// Pseudocode (subtree-to-processor mapping; Geist & Ng, "Task scheduling for parallel sparse
// Cholesky factorization", Int. J. Parallel Programming 18, 1989):
//   weight(v) ← the blocks of L in column v, diagonal included; load(v) ← over v's subtree
//   candidates ← the roots; top ← ∅
//   repeat:
//     deal the candidates, heaviest first, each to the lighter part
//     keep the split if max(part loads) + weight(top) is the least so far
//     move the heaviest candidate to the top, its children into the candidates
//   until no candidate is left, or the top alone weighs as much as the best split, or the
//   heaviest candidate is a twentieth of all (dealing is then balanced to 5%)
void BlockCholesky::split_elimination_tree() {
  const int n = block_count_;
  std::vector<long> load(n);
  for (int k = 0; k < n; ++k) load[k] = column_start_[k + 1] - column_start_[k] + 1;
  const std::vector<long> weight = load;
  for (int k = 0; k < n; ++k)
    if (parent_[k] >= 0) load[parent_[k]] += load[k];
  std::vector<std::vector<int>> children(n);
  std::vector<int> candidates;
  for (int k = 0; k < n; ++k) (parent_[k] >= 0 ? children[parent_[k]] : candidates).push_back(k);
  // Heaviest first; ties by position, so that the split is the same on every machine.
  const auto heavier = [&](int a, int b) { return load[a] != load[b] ? load[a] > load[b] : a < b; };
  const auto deal = [&](const std::vector<int>& sorted, std::vector<int>* part_of_root) {
    std::array<long, 2> parts{0, 0};
    for (int v : sorted) {
      const int p = parts[1] < parts[0] ? 1 : 0;
      parts[p] += load[v];
      if (part_of_root) (*part_of_root)[v] = p;
    }
    return std::max(parts[0], parts[1]);
  };
  std::sort(candidates.begin(), candidates.end(), heavier);
  std::vector<int> moved;  // candidates moved to the top, in turn
  long top_weight = 0;
  long best_cost = deal(candidates, nullptr);
  std::size_t best_moves = 0;
  std::vector<int> best_candidates = candidates;
  long candidate_load = 0;
  for (int v : candidates) candidate_load += load[v];
  // Dealt heaviest first, the parts differ by at most the heaviest candidate: once that is a
  // twentieth of the whole, splitting further only grows the top. (A forest of many small
  // trees, a packing's blocks that touch nothing, is there at once.) The moves are capped too.
  const auto worth_splitting = [&] { return 20 * load[candidates.front()] > candidate_load && moved.size() < 256; };
  while (!candidates.empty() && top_weight < best_cost && worth_splitting()) {
    const int v = candidates.front();
    candidates.erase(candidates.begin());
    moved.push_back(v);
    top_weight += weight[v];
    candidate_load -= weight[v];
    for (int c : children[v]) candidates.insert(std::upper_bound(candidates.begin(), candidates.end(), c, heavier), c);
    const long cost = deal(candidates, nullptr) + top_weight;
    if (cost < best_cost) {
      best_cost = cost;
      best_moves = moved.size();
      best_candidates = candidates;
    }
  }
  // The best split: its top, its candidates dealt, every other node in its root's part.
  std::vector<char> in_top(n, 0);
  for (std::size_t m = 0; m < best_moves; ++m) in_top[moved[m]] = 1;
  std::vector<int> part_of(n, 2);
  deal(best_candidates, &part_of);
  for (int k = n - 1; k >= 0; --k)
    if (!in_top[k] && parent_[k] >= 0 && !in_top[parent_[k]]) part_of[k] = part_of[parent_[k]];
  for (auto& columns : part_columns_) columns.clear();
  top_index_.assign(n, -1);
  for (int k = 0; k < n; ++k) {
    if (part_of[k] == 2) top_index_[k] = static_cast<int>(part_columns_[2].size());
    part_columns_[part_of[k]].push_back(k);
  }
}

std::array<long, 3> BlockCholesky::part_blocks() const {
  std::array<long, 3> blocks{0, 0, 0};
  for (int p = 0; p < 3; ++p)
    for (int k : part_columns_[p]) blocks[p] += column_start_[k + 1] - column_start_[k] + 1;
  return blocks;
}

// Below some 5,000 blocks of L a sweep takes tens of microseconds, and waking a second thread
// costs as much as it saves.
bool BlockCholesky::run_parts_in_parallel() const { return column_start_.back() + block_count_ >= 5000; }

struct BlockCholesky::Sweep {
  const int* column_start;
  const int* row;
  const Matrix6* value;
  const Matrix6* inverse_diagonal;
  const int* top_rows_start;  // per column: its rows from here on are the top's
  const int* top_index;
};

namespace {

// The triangular sweeps over L's block columns, on u in elimination order, 6×6 blocks column
// major. The portable form is Eigen's; on a CPU with AVX2 and FMA a hand-vectorised form
// (bench_dda, BM_WallGraphTriangularSolves: 13% faster on the wall's factor) is chosen when
// the program starts. Eigen picks its SIMD width at compile time and, for the baseline x86-64
// build, 6-vectors get 2-wide SSE2 only.
//
// Forward, by columns: u_k ← L_kk⁻¹ u_k; u_r −= L_rk u_k for the rows r of column k.
// Backward, by rows of Lᵀ: u_k ← L_kk⁻ᵀ (u_k − Σ_r L_rkᵀ u_r).
using Sweep = BlockCholesky::Sweep;

// One column of the forward sweep: its updates to rows before `split` go to u, those from
// `split` on (the top's rows, for a column of a part) to `top_updates` by top index.
void forward_column(const Sweep& l, int k, int split, double* u, double* top_updates) {
  Eigen::Map<Vector6> uk(u + 6 * k);
  // The inverse is lower triangular; a full fixed-size product is faster than a triangular one.
  const Vector6 yk = l.inverse_diagonal[k] * uk;
  uk = yk;
  int q = l.column_start[k];
  for (; q < split; ++q) Eigen::Map<Vector6>(u + 6 * l.row[q]).noalias() -= l.value[q] * yk;
  for (; q < l.column_start[k + 1]; ++q)
    Eigen::Map<Vector6>(top_updates + 6 * l.top_index[l.row[q]]).noalias() -= l.value[q] * yk;
}

// The forward sweep over some columns, ascending.
void forward_portable(const Sweep& l, const std::vector<int>& columns, double* u, double* top_updates) {
  for (int k : columns) forward_column(l, k, l.top_rows_start[k], u, top_updates);
}

// The backward sweep over some columns, descending; every row they read is final.
void backward_portable(const Sweep& l, const std::vector<int>& columns, double* u) {
  for (auto c = columns.rbegin(); c != columns.rend(); ++c) {
    const int k = *c;
    Eigen::Map<Vector6> uk(u + 6 * k);
    Vector6 t = uk;
    for (int q = l.column_start[k]; q < l.column_start[k + 1]; ++q)
      t.noalias() -= l.value[q].transpose() * Eigen::Map<const Vector6>(u + 6 * l.row[q]);
    uk.noalias() = l.inverse_diagonal[k].transpose() * t;
  }
}

#if defined(__x86_64__)
// A 6-vector as a 4-wide and a 2-wide register: target −= v y, y's entries broadcast.
[[gnu::target("avx2,fma")]] inline void subtract_product_avx2(const double* v, const __m256d* y, double* target) {
  __m256d head = _mm256_loadu_pd(target);
  __m128d tail = _mm_loadu_pd(target + 4);
  for (int j = 0; j < 6; ++j) {
    head = _mm256_fnmadd_pd(_mm256_loadu_pd(v + 6 * j), y[j], head);
    tail = _mm_fnmadd_pd(_mm_loadu_pd(v + 6 * j + 4), _mm256_castpd256_pd128(y[j]), tail);
  }
  _mm256_storeu_pd(target, head);
  _mm_storeu_pd(target + 4, tail);
}

[[gnu::target("avx2,fma")]] void forward_avx2(const Sweep& l, const std::vector<int>& columns, double* u,
                                             double* top_updates) {
  for (int k : columns) {
    Eigen::Map<Vector6> uk(u + 6 * k);
    const Vector6 yk = l.inverse_diagonal[k] * uk;
    uk = yk;
    __m256d y[6];
    for (int j = 0; j < 6; ++j) y[j] = _mm256_set1_pd(yk[j]);
    int q = l.column_start[k];
    for (; q < l.top_rows_start[k]; ++q) subtract_product_avx2(l.value[q].data(), y, u + 6 * l.row[q]);
    for (; q < l.column_start[k + 1]; ++q)
      subtract_product_avx2(l.value[q].data(), y, top_updates + 6 * l.top_index[l.row[q]]);
  }
}

// Σ_r L_rkᵀ u_r: column j of each block times u_r, elementwise into one accumulator per j,
// summed across once per k.
[[gnu::target("avx2,fma")]] void backward_avx2(const Sweep& l, const std::vector<int>& columns, double* u) {
  for (auto c = columns.rbegin(); c != columns.rend(); ++c) {
    const int k = *c;
    __m256d head[6];
    __m128d tail[6];
    for (int j = 0; j < 6; ++j) {
      head[j] = _mm256_setzero_pd();
      tail[j] = _mm_setzero_pd();
    }
    for (int q = l.column_start[k]; q < l.column_start[k + 1]; ++q) {
      const double* v = l.value[q].data();
      const double* source = u + 6 * l.row[q];
      const __m256d s_head = _mm256_loadu_pd(source);
      const __m128d s_tail = _mm_loadu_pd(source + 4);
      for (int j = 0; j < 6; ++j) {
        head[j] = _mm256_fmadd_pd(_mm256_loadu_pd(v + 6 * j), s_head, head[j]);
        tail[j] = _mm_fmadd_pd(_mm_loadu_pd(v + 6 * j + 4), s_tail, tail[j]);
      }
    }
    Eigen::Map<Vector6> uk(u + 6 * k);
    Vector6 t;
    for (int j = 0; j < 6; ++j) {
      const __m128d h = _mm_add_pd(_mm_add_pd(_mm256_castpd256_pd128(head[j]), _mm256_extractf128_pd(head[j], 1)),
                                   tail[j]);
      t[j] = uk[j] - (_mm_cvtsd_f64(h) + _mm_cvtsd_f64(_mm_unpackhi_pd(h, h)));
    }
    uk.noalias() = l.inverse_diagonal[k].transpose() * t;
  }
}

void forward_sweep(const Sweep& l, const std::vector<int>& columns, double* u, double* top_updates) {
  vectorised ? forward_avx2(l, columns, u, top_updates) : forward_portable(l, columns, u, top_updates);
}
void backward_sweep(const Sweep& l, const std::vector<int>& columns, double* u) {
  vectorised ? backward_avx2(l, columns, u) : backward_portable(l, columns, u);
}
#else
void forward_sweep(const Sweep& l, const std::vector<int>& columns, double* u, double* top_updates) {
  forward_portable(l, columns, u, top_updates);
}
void backward_sweep(const Sweep& l, const std::vector<int>& columns, double* u) {
  backward_portable(l, columns, u);
}
#endif

}  // namespace

BlockCholesky::Sweep BlockCholesky::sweep() const {
  return {column_start_.data(),     row_.data(),            value_.data(),
          inverse_diagonal_.data(), top_rows_start_.data(), top_index_.data()};
}

// The two parts, each with the top's updates in its own buffer; then the top, once both
// parts' updates are in.
void BlockCholesky::forward(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& u) const {
  const int n = block_count_;
  u.resize(6 * n);
  for (int k = 0; k < n; ++k) u.segment<6>(6 * k) = x.segment<6>(6 * order_[k]);
  const Sweep l = sweep();
  numerics::run_two_parts(run_parts_in_parallel(),
                [&](int p) { forward_sweep(l, part_columns_[p], u.data(), top_updates_[p].data()); });
  const std::vector<int>& top = part_columns_[2];
  for (std::size_t t = 0; t < top.size(); ++t) {
    for (Eigen::VectorXd& updates : top_updates_) {
      u.segment<6>(6 * top[t]) += updates.segment<6>(6 * t);
      updates.segment<6>(6 * t).setZero();
    }
  }
  forward_sweep(l, top, u.data(), nullptr);
}

// The top first, then the two parts, which read only it and themselves.
void BlockCholesky::backward(Eigen::VectorXd& u, Eigen::Ref<Eigen::VectorXd> x) const {
  const Sweep l = sweep();
  backward_sweep(l, part_columns_[2], u.data());
  numerics::run_two_parts(run_parts_in_parallel(), [&](int p) { backward_sweep(l, part_columns_[p], u.data()); });
  for (int k = 0; k < block_count_; ++k) x.segment<6>(6 * order_[k]) = u.segment<6>(6 * k);
}

void BlockCholesky::solve_in_place(Eigen::Ref<Eigen::VectorXd> x) const {
  forward(x, work_);
  backward(work_, x);
}

// Pseudocode: mark the tree paths from the positions of b's blocks to the root; the marked
// positions ascending are the nonzeros of L⁻¹ P b (a column of L has rows only on its own
// path); sweep forward over them alone. path_work_ and on_path_ are zero off the path before
// and after, so nothing here costs more than the path.
BlockCholesky::SparseVector BlockCholesky::forward_sparse(const SparseVector& b) const {
  SparseVector y;
  for (std::size_t e = 0; e < b.blocks.size(); ++e) {
    const int start = position_[b.blocks[e]];
    path_work_.segment<6>(6 * start) += b.values[e];
    for (int k = start; k != -1 && !on_path_[k]; k = parent_[k]) {
      on_path_[k] = 1;
      y.blocks.push_back(k);
    }
  }
  std::sort(y.blocks.begin(), y.blocks.end());
  y.values.reserve(y.blocks.size());
  const Sweep l = sweep();
  for (int k : y.blocks) {
    forward_column(l, k, l.column_start[k + 1], path_work_.data(), nullptr);
    y.values.push_back(path_work_.segment<6>(6 * k));
  }
  for (int k : y.blocks) {
    path_work_.segment<6>(6 * k).setZero();
    on_path_[k] = 0;
  }
  return y;
}

}  // namespace hydrodda::dda
