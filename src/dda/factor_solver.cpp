// The default DDA solver: a kept block Cholesky factor (block_cholesky.hpp) as the
// preconditioner of conjugate gradients on the current matrix.
//
// A DDA step changes its matrix in two ways: every contact whose state flips (open, sliding,
// locked) adds or removes a penalty spring, a rank-one term w wᵀ over two blocks; and the
// geometry moves a little, which changes every entry slightly. So the factor P = L Lᵀ is kept
// from one open–close pass and one step to the next:
//   factor(A, terms):  the springs that appeared (+) or disappeared (−) since P was made
//                      become a low-rank correction M = P + W S Wᵀ, S = diag(±1). With
//                      P = Πᵀ L Lᵀ Π and Y = L⁻¹ Π W, M = Πᵀ L (I + Y S Yᵀ) Lᵀ Π, and by the
//                      Sherman–Morrison–Woodbury identity
//                        M⁻¹ = Πᵀ L⁻ᵀ (I − Y C⁻¹ Yᵀ) L⁻¹ Π,   C = S⁻¹ + Yᵀ Y
//                      (Hager, "Updating the inverse of a matrix", SIAM Review 31, 1989;
//                      numerics/woodbury.hpp).
//                      A spring spans two blocks, so its column of Y is nonzero only on their
//                      paths to the root of the elimination tree: a sparse half-solve each.
//   solve(b):          conjugate gradients on the current A preconditioned by M (Saad,
//                      alg. 9.1) from the last solution; M differs from A by the geometric
//                      drift only, so a few iterations reach ‖b − A x‖ ≤ tol ‖b‖.
// When the corrections grow past kMaxCorrections, or CG needs more than kRefactorAfterIterations
// iterations (the drift has grown; kept_factor_solver.hpp), A is factored afresh.
#include <algorithm>
#include <stdexcept>

#include <Eigen/Dense>

#include "dda/block_cholesky.hpp"
#include "dda/kept_factor_solver.hpp"
#include "numerics/woodbury.hpp"

namespace hydrodda::dda {
namespace {

// One spring of the low-rank correction: its vector w as the factor knew it (removed springs)
// or as it came (added ones), the sign of w wᵀ, and its column of Y.
struct Correction {
  RankOneTerm term;
  double sign = 1.0;
  BlockCholesky::SparseVector y;  // L⁻¹ Π w, in elimination positions
};

// Σ over the positions both hold of a_k · b_k (both in ascending positions).
double sparse_dot(const BlockCholesky::SparseVector& a, const BlockCholesky::SparseVector& b) {
  double s = 0.0;
  std::size_t i = 0, j = 0;
  while (i < a.blocks.size() && j < b.blocks.size()) {
    if (a.blocks[i] < b.blocks[j]) {
      ++i;
    } else if (b.blocks[j] < a.blocks[i]) {
      ++j;
    } else {
      s += a.values[i++].dot(b.values[j++]);
    }
  }
  return s;
}

class BlockFactorSolver final : public KeptFactorSolver {
 public:
  BlockFactorSolver(double tolerance, int max_iterations) : KeptFactorSolver(tolerance, max_iterations) {}

  void factor(const BlockMatrix& base, const RankOneTerms& terms) override {
    own_base_ = base;
    own_terms_ = terms;
    take_matrix(own_base_, own_terms_);
  }

  void factor_borrowing(const BlockMatrix& base, const RankOneTerms& terms) override { take_matrix(base, terms); }

  void reset() override {
    factor_.clear();
    order_.clear();
    block_count_ = -1;
    base_ = nullptr;
    terms_ = nullptr;
    own_base_ = BlockMatrix{};
    // Their memory too (a restart's state is a coupled run's between passes).
    own_terms_ = {};
    factored_terms_ = {};
    corrections_ = {};
    capacitance_matrix_ = {};
    product_ = {};
    forget_solution();
  }

 private:
  // Past this many springs changed since the factorisation, the correction (m sparse columns
  // and an m × m capacitance) costs more per application than a fresh factorisation saves
  // (the limit measured on the 1,601-block wall: docs/studies/2026-11-29-wall-chatter-across-steps.md).
  static constexpr std::size_t kMaxCorrections = 64;

  // The matrix is now base + terms.
  void take_matrix(const BlockMatrix& base, const RankOneTerms& terms) {
    if (base.block_count != block_count_) {
      block_count_ = base.block_count;
      order_.clear();  // ordered at the next factorisation, on the pattern of the matrix and its springs
      factor_.clear();
      stale_ = true;
    }
    base_ = &base;
    terms_ = &terms;
    product_.reset(base, terms);
    if (!factor_.empty() && !stale_ && !follow_terms()) stale_ = true;
  }

  // Brings the correction up to the springs of the current matrix. False if there are too
  // many changes to follow.
  bool follow_terms() {
    // What appeared (+), what disappeared (−), each in id order.
    RankOneTerms added, removed;
    if (!find_changed_terms(*terms_, factored_terms_, kMaxCorrections, added, removed)) return false;
    // Keep the corrections already made (same spring, same sign) with their rows of C; the new
    // ones after them, one sparse half-solve each. A binary search in the sorted lists finds
    // each kept one, where a search through all of them made following m springs cost m².
    const auto index_in = [](const RankOneTerms& list, const RankOneTerm& t) -> std::ptrdiff_t {
      const auto at = std::lower_bound(list.begin(), list.end(), t.id,
                                       [](const RankOneTerm& a, const std::array<int, 5>& id) { return a.id < id; });
      return at != list.end() && at->id == t.id ? at - list.begin() : -1;
    };
    std::vector<char> added_kept(added.size(), 0), removed_kept(removed.size(), 0);
    std::vector<Eigen::Index> kept_rows;
    for (std::size_t k = 0; k < corrections_.size(); ++k) {
      const Correction& c = corrections_[k];
      const RankOneTerms& list = c.sign > 0 ? added : removed;
      const std::ptrdiff_t at = index_in(list, c.term);
      if (at < 0) continue;
      (c.sign > 0 ? added_kept : removed_kept)[static_cast<std::size_t>(at)] = 1;
      if (kept_rows.size() != k) corrections_[kept_rows.size()] = std::move(corrections_[k]);
      kept_rows.push_back(static_cast<Eigen::Index>(k));
    }
    const std::size_t kept = kept_rows.size();
    const bool all_kept = kept == corrections_.size();
    corrections_.resize(kept);
    const auto add_correction = [&](const RankOneTerm& t, double sign) {
      Correction c{t, sign, {}};
      BlockCholesky::SparseVector spring;
      if (t.block_a >= 0) {
        spring.blocks.push_back(t.block_a);
        spring.values.push_back(t.w_a);
      }
      if (t.block_b >= 0) {
        spring.blocks.push_back(t.block_b);
        spring.values.push_back(t.w_b);
      }
      c.y = factor_.forward_sparse(spring);
      corrections_.push_back(std::move(c));
      ++counts_.modified_terms;
    };
    for (std::size_t a = 0; a < added.size(); ++a)
      if (!added_kept[a]) add_correction(added[a], 1.0);
    for (std::size_t a = 0; a < removed.size(); ++a)
      if (!removed_kept[a]) add_correction(removed[a], -1.0);
    if (!all_kept || corrections_.size() != kept) update_capacitance(kept_rows);
    return true;
  }

  // C = S⁻¹ + Yᵀ Y, factored: the entries of the kept corrections (rows `kept_rows` of the
  // last C, in their new order) taken over, those of the new ones, after them, computed.
  void update_capacitance(const std::vector<Eigen::Index>& kept_rows) {
    const auto m = static_cast<Eigen::Index>(corrections_.size());
    const auto kept = static_cast<Eigen::Index>(kept_rows.size());
    Eigen::MatrixXd c(m, m);
    for (Eigen::Index b = 0; b < kept; ++b)
      for (Eigen::Index a = 0; a <= b; ++a) c(a, b) = c(b, a) = capacitance_matrix_(kept_rows[a], kept_rows[b]);
    for (Eigen::Index b = kept; b < m; ++b) {
      for (Eigen::Index a = 0; a <= b; ++a) c(a, b) = c(b, a) = sparse_dot(corrections_[a].y, corrections_[b].y);
      c(b, b) += 1.0 / corrections_[b].sign;
    }
    capacitance_matrix_ = std::move(c);
    capacitance_.factor(capacitance_matrix_);
  }

  // z = M⁻¹ r: u = L⁻¹ Π r; u −= Y C⁻¹ Yᵀ u; z = Πᵀ L⁻ᵀ u.
  void apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
    factor_.forward(r, u_);
    if (!corrections_.empty()) {
      Eigen::VectorXd t(corrections_.size());
      for (std::size_t a = 0; a < corrections_.size(); ++a) {
        const BlockCholesky::SparseVector& y = corrections_[a].y;
        double s = 0.0;
        for (std::size_t e = 0; e < y.blocks.size(); ++e) s += y.values[e].dot(u_.segment<6>(6 * y.blocks[e]));
        t[static_cast<Eigen::Index>(a)] = s;
      }
      const Eigen::VectorXd coefficients = capacitance_.solve(t);
      for (std::size_t a = 0; a < corrections_.size(); ++a) {
        const BlockCholesky::SparseVector& y = corrections_[a].y;
        const double c = coefficients[static_cast<Eigen::Index>(a)];
        for (std::size_t e = 0; e < y.blocks.size(); ++e) u_.segment<6>(6 * y.blocks[e]) -= c * y.values[e];
      }
    }
    z.resize(r.size());
    factor_.backward(u_, z);
  }

  // By CG from `guess`, preconditioned by the kept factor or a fresh one.
  Eigen::VectorXd solve_to(const Eigen::VectorXd& b, const Eigen::VectorXd& guess, double tolerance,
                           int& iterations) const override {
    const bool kept = !factor_.empty() && !stale_;
    if (!kept) refactor();
    Eigen::VectorXd x;
    iterations = run_preconditioned_cg(b, guess, tolerance, x);
    // A kept factor that no longer serves: factor the matrix itself, with which CG converges
    // at once unless the matrix is too ill-conditioned to solve.
    if (iterations < 0 && kept) {
      refactor();
      iterations = run_preconditioned_cg(b, guess, tolerance, x);
    }
    if (iterations < 0)
      throw std::runtime_error(
          "DDA: the stiffness solve did not converge even on a fresh factorisation: the matrix is "
          "numerically singular");
    return x;
  }

  // CG on the current matrix, preconditioned by the corrected factor.
  int run_preconditioned_cg(const Eigen::VectorXd& b, const Eigen::VectorXd& guess, double tolerance,
                            Eigen::VectorXd& x) const {
    return numerics::solve_by_conjugate_gradients(
        [this](const Eigen::VectorXd& v, Eigen::VectorXd& y) { product_.multiply(v, y); },
        [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { apply_preconditioner(r, z); }, b, guess,
        tolerance, max_iterations_, x, counts_.iterations);
  }

  void refactor() const {
    ++counts_.factorisations;
    // Minimum degree on the block graph of the first matrix; later contacts change the fill a
    // little, not the correctness.
    if (order_.empty()) order_ = order_by_minimum_degree(*base_, *terms_);
    // The springs are read where they are, not assembled first.
    if (!factor_.factorise(*base_, *terms_, order_)) {
      if (!all_finite(*base_, *terms_))
        throw std::runtime_error("DDA: the global stiffness matrix has entries that are not finite "
                                 "(an overflow in the model's data)");
      throw std::runtime_error("DDA: the global stiffness matrix is not positive definite");
    }
    factored_terms_ = *terms_;
    corrections_.clear();
    stale_ = false;
  }

  mutable std::vector<int> order_;
  // The matrix is *base_ + the springs *terms_: the caller's (factor_borrowing) or own_base_
  // and own_terms_ (factor).
  const BlockMatrix* base_ = nullptr;
  const RankOneTerms* terms_ = nullptr;
  SpringMatrixProduct product_;  // y = (*base_ + *terms_) x
  BlockMatrix own_base_;
  RankOneTerms own_terms_;
  int block_count_ = -1;  // of the last matrix
  mutable RankOneTerms factored_terms_;  // as held by the factor
  mutable BlockCholesky factor_;
  mutable std::vector<Correction> corrections_;
  mutable Eigen::MatrixXd capacitance_matrix_;  // C, unfactored, in the order of corrections_
  mutable numerics::WoodburyCapacitance capacitance_;
  mutable Eigen::VectorXd u_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_block_factor_solver(double tolerance, int max_iterations) {
  return std::make_unique<BlockFactorSolver>(tolerance, max_iterations);
}

}  // namespace hydrodda::dda
