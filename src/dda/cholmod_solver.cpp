// CHOLMOD behind LinearSolver: the only file of the DDA module that includes cholmod.h.
//
// A DDA step changes its matrix in two ways: every contact whose state flips (open, sliding,
// locked) adds or removes a penalty spring, a rank-one term √p e (√p e)ᵀ over two blocks;
// and the geometry moves a little, which changes every entry slightly. Factoring afresh for
// every open–close iteration dominated the step (bench_dda), so the factor is kept:
//   factor(A, terms):  for the terms that appeared since the factor was made: update L;
//                      for those that disappeared: downdate L (with the vector it was made with)
//   solve(b):          conjugate gradients on the current A preconditioned by L (Saad,
//                      alg. 9.1), from the last solution; L differs from A only by the
//                      geometric drift, so a few iterations reach ‖b − A x‖ ≤ tol ‖b‖. When
//                      they do not (the drift has grown, or an update failed or was not worth
//                      making), A is factored again and solved directly.
// Updates and downdates: Davis & Hager, "Multiple-rank modifications of a sparse Cholesky
// factorization", SIAM J. Matrix Anal. Appl. 22 (2001), as CHOLMOD's Modify module does them;
// they need the simplicial LDLᵀ form, which also beat the supernodal one on these very sparse
// 2D block graphs with the reference BLAS (bench_dda).
#include <cholmod.h>

#include <algorithm>
#include <stdexcept>

#include "dda/kept_factor_solver.hpp"

namespace hydrodda::dda {
namespace {

bool id_less(const RankOneTerm& a, const RankOneTerm& b) { return a.id < b.id; }

class CholmodSolver final : public KeptFactorSolver {
 public:
  CholmodSolver(double tolerance, int max_iterations) : KeptFactorSolver(tolerance, max_iterations) {
    cholmod_start(&common_);
    // Our block AMD order, kept as given; simplicial LDLᵀ (what updates work on).
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_GIVEN;
    common_.supernodal = CHOLMOD_SIMPLICIAL;
    common_.final_ll = false;
    common_.print = 0;
  }
  ~CholmodSolver() override {
    cholmod_free_factor(&factor_, &common_);
    cholmod_free_dense(&solution_, &common_);
    cholmod_free_dense(&work_y_, &common_);
    cholmod_free_dense(&work_e_, &common_);
    cholmod_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  void factor(const BlockMatrix& base, const RankOneTerms& terms) override {
    BlockMatrix& a = assembled_;
    add_springs(base, terms, a);
    if (ordering_.empty() || a.block_count != block_count_) compute_ordering(a);
    matrix_ = a.lower_triangle();
    if (factor_ != nullptr && !stale_) {
      if (!follow_terms(terms)) stale_ = true;
    }
    terms_ = terms;
  }

  void reset() override {
    cholmod_free_factor(&factor_, &common_);
    ordering_.clear();
    inverse_order_.clear();
    block_count_ = -1;
    terms_.clear();
    factored_terms_.clear();
    forget_solution();
  }

 private:
  // CG from `guess` preconditioned by the kept factor, or, when there is none or CG does not
  // get there, a direct solve on a fresh one (0 iterations).
  Eigen::VectorXd solve_to(const Eigen::VectorXd& b, const Eigen::VectorXd& guess, double tolerance,
                           int& iterations) const override {
    Eigen::VectorXd x;
    iterations = 0;
    if (factor_ != nullptr && !stale_) {
      iterations = numerics::solve_by_conjugate_gradients(
          [this](const Eigen::VectorXd& v, Eigen::VectorXd& y) { y = multiply(v); },
          [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = apply_factor(r); }, b, guess, tolerance,
          max_iterations_, x, counts_.iterations);
      if (iterations >= 0) return x;
    }
    iterations = 0;
    refactor();
    x = apply_factor(b);
    // One refinement step against round-off in the deep contact stiffness.
    x += apply_factor(b - multiply(x));
    return x;
  }

  // Updates L by the terms new since it was made and downdates it by those gone, in place.
  // False if it did not: too many changes at once, or a downdate CHOLMOD could not make (one
  // that would lose positive definiteness).
  bool follow_terms(const RankOneTerms& terms) {
    // Many changes at once (contacts landing all over a settling packing): each update walks
    // a path of L, and past a quarter of the block count a fresh factorisation costs less
    // (bench_dda: the 1,601-block packing went from 709 to 95 ms a step, the wall unchanged).
    if (!find_changed_terms(terms, factored_terms_, static_cast<std::size_t>(block_count_) / 4, added_, removed_))
      return false;
    if (added_.empty() && removed_.empty()) return true;
    if (!modify_factor(added_, true) || !modify_factor(removed_, false)) return false;
    // What L now holds: the kept terms as they were made, and the new ones.
    RankOneTerms held;
    held.reserve(terms.size());
    std::set_difference(factored_terms_.begin(), factored_terms_.end(), removed_.begin(), removed_.end(),
                        std::back_inserter(held), id_less);
    factored_terms_.clear();
    std::merge(held.begin(), held.end(), added_.begin(), added_.end(), std::back_inserter(factored_terms_),
               id_less);
    return true;
  }

  // L D Lᵀ ← L D Lᵀ ± C Cᵀ, C's columns the terms' vectors in the factor's row order.
  bool modify_factor(const RankOneTerms& terms, bool update) {
    if (terms.empty()) return true;
    const int n = static_cast<int>(matrix_.rows());
    cholmod_sparse* c = cholmod_allocate_sparse(n, terms.size(), 12 * terms.size(), true, true, 0,
                                                CHOLMOD_REAL, &common_);
    if (c == nullptr) return false;
    int* cp = static_cast<int*>(c->p);
    int* ci = static_cast<int*>(c->i);
    double* cx = static_cast<double*>(c->x);
    int nz = 0;
    std::vector<std::pair<int, double>> column;
    for (std::size_t k = 0; k < terms.size(); ++k) {
      cp[k] = nz;
      column.clear();
      const RankOneTerm& t = terms[k];
      for (int r = 0; r < 6; ++r) {
        if (t.block_a >= 0) column.emplace_back(inverse_order_[6 * t.block_a + r], t.w_a[r]);
        if (t.block_b >= 0) column.emplace_back(inverse_order_[6 * t.block_b + r], t.w_b[r]);
      }
      std::sort(column.begin(), column.end());
      for (auto [row, value] : column) {
        ci[nz] = row;
        cx[nz++] = value;
      }
    }
    cp[terms.size()] = nz;
    counts_.modified_terms += static_cast<long>(terms.size());
    const int ok = cholmod_updown(update ? 1 : 0, c, factor_, &common_);
    cholmod_free_sparse(&c, &common_);
    return ok == 1 && common_.status == CHOLMOD_OK;
  }

  Eigen::VectorXd multiply(const Eigen::VectorXd& v) const {
    return matrix_.selfadjointView<Eigen::Lower>() * v;
  }

  // x = (P A Pᵀ)⁻¹ b through the factor (CHOLMOD applies the permutation).
  Eigen::VectorXd apply_factor(const Eigen::VectorXd& b) const {
    cholmod_dense rhs{};
    rhs.nrow = b.size();
    rhs.ncol = 1;
    rhs.nzmax = b.size();
    rhs.d = b.size();
    rhs.x = const_cast<double*>(b.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    if (!cholmod_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &solution_, nullptr, &work_y_, &work_e_,
                        &common_))
      throw std::runtime_error("DDA: the factorised solve failed");
    return Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(solution_->x), b.size());
  }

  cholmod_sparse view_of_matrix() const {
    cholmod_sparse a{};
    a.nrow = a.ncol = matrix_.rows();
    a.nzmax = matrix_.nonZeros();
    a.p = const_cast<int*>(matrix_.outerIndexPtr());
    a.i = const_cast<int*>(matrix_.innerIndexPtr());
    a.x = const_cast<double*>(matrix_.valuePtr());
    a.stype = -1;  // the lower triangle of a symmetric matrix
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
  }

  // Analysis (with our order) and numeric factorisation of the current matrix. The analysis
  // is redone every time: updates may have grown L's pattern beyond the last analysis, and
  // with a given order it costs a small part of the factorisation.
  void refactor() const {
    cholmod_sparse a = view_of_matrix();
    cholmod_free_factor(&factor_, &common_);
    factor_ = cholmod_analyze_p(&a, const_cast<int*>(ordering_.data()), nullptr, 0, &common_);
    if (factor_ == nullptr) throw std::runtime_error("DDA: the stiffness matrix could not be analysed");
    ++counts_.factorisations;
    if (!cholmod_factorize(&a, factor_, &common_) || common_.status != CHOLMOD_OK)
      throw std::runtime_error("DDA: the global stiffness matrix is not positive definite");
    // CHOLMOD post-orders the given order: the factor's own permutation is the one to use.
    const int* perm = static_cast<const int*>(factor_->Perm);
    inverse_order_.resize(factor_->n);
    for (std::size_t k = 0; k < factor_->n; ++k) inverse_order_[perm[k]] = static_cast<int>(k);
    factored_terms_ = terms_;
    stale_ = false;
  }

  // Minimum degree on the block graph, expanded to the unknowns. The graph is that of the
  // first matrix; later contacts change the fill a little, not the correctness.
  void compute_ordering(const BlockMatrix& a) {
    const std::vector<int> blocks = order_by_minimum_degree(a);
    // CHOLMOD's convention for a given order is the same: position k → the unknown eliminated k-th.
    ordering_.resize(6 * a.block_count);
    for (int k = 0; k < a.block_count; ++k)
      for (int r = 0; r < 6; ++r) ordering_[6 * k + r] = 6 * blocks[k] + r;
    block_count_ = a.block_count;
    cholmod_free_factor(&factor_, &common_);
  }

  mutable cholmod_common common_{};
  mutable cholmod_factor* factor_ = nullptr;
  mutable cholmod_dense* solution_ = nullptr;
  mutable cholmod_dense* work_y_ = nullptr;
  mutable cholmod_dense* work_e_ = nullptr;
  std::vector<int> ordering_;  // ordering_[k]: the unknown eliminated k-th
  mutable std::vector<int> inverse_order_;
  int block_count_ = -1;
  SparseMatrix matrix_;
  RankOneTerms terms_;                   // of the current matrix
  BlockMatrix assembled_;                // base + springs, its memory reused
  mutable RankOneTerms factored_terms_;  // as held by the factor
  RankOneTerms added_, removed_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver(double tolerance, int max_iterations) {
  return std::make_unique<CholmodSolver>(tolerance, max_iterations);
}

}  // namespace hydrodda::dda
