#pragma once
// The numeric supernodal Cholesky factorisation of a CHOLMOD analysis, on two threads: the
// supernodes of the two halves a vertex separator leaves (nested_dissection.hpp) are
// factored side by side, the separator's after both. Written by hand because CHOLMOD's own
// (cholmod_factorize) works its supernodes one after the other: at a million triangles it
// keeps one core of two busy for 0.56 s a pass. The factor it fills is CHOLMOD's, so that
// cholmod_solve and the low-rank correction read it as they read CHOLMOD's.

#include <cholmod.h>

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "numerics/cholmod_solver.hpp"
#include "numerics/supernodal_correction.hpp"

namespace hydrodda::numerics {

// Gives CHOLMOD back a block of `doubles` doubles' worth that it allocated.
struct CholmodValues {
  cholmod_common* common = nullptr;
  std::size_t doubles = 0;
  void operator()(float* values) const;
};

class SupernodalFactorization {
 public:
  // `factor`: CHOLMOD's supernodal analysis (int indices) of the matrix whose upper triangle
  // `upper` holds (its values are not read here). part[u] is 0 or 1 for an unknown of either
  // half, 2 for the separator's (any part where no split was made: empty `part`). Throws
  // std::logic_error when `factor` is not such an analysis.
  SupernodalFactorization(cholmod_factor* factor, cholmod_common* common, const SparseMatrix& upper,
                          std::span<const int> part);

  // Fills `factor` with the LLᵀ factor of P A Pᵀ, A the matrix with the analysed pattern whose
  // upper triangle is `upper`; the halves on two threads where `two_threads`. The values are
  // the same either way, bit for bit. Throws SingularSystem where A is not positive definite.
  void factorize(const SparseMatrix& upper, bool two_threads);

  // x = A⁻¹ b = Pᵀ L⁻ᵀ L⁻¹ P b with the factor this object filled; the halves on two threads
  // where `two_threads`, with the same values either way, bit for bit. Kept in single
  // precision, the factor is L̃ (below) and x = Pᵀ L̃⁻ᵀ L̃⁻¹ P b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b, bool two_threads) const;
  // Its two halves: v ← L⁻¹ P v, and v ← Pᵀ L⁻ᵀ v.
  void solve_forward(Eigen::VectorXd& v, bool two_threads) const;
  void solve_backward(Eigen::VectorXd& v, bool two_threads) const;

  // Keeps the factor as L̃, its values rounded to single precision, and lets the double ones go
  // (CHOLMOD's factor is symbolic again) until the next factorize(): for a factor that serves
  // as a preconditioner only. Half the memory (130 MB at 10^6 triangles), and half the memory
  // each solve reads. The solves then run in double arithmetic on L̃'s
  // values: they apply (Pᵀ L̃ L̃ᵀ P)⁻¹ exactly, a fixed symmetric positive definite operator.
  // Throws std::logic_error before a factorisation.
  void keep_in_single_precision();
  bool in_single_precision() const { return single_ != nullptr; }
  // L̃'s values, in CHOLMOD's layout (the factor's px), or null while the factor is in double.
  const float* single_values() const { return single_.get(); }

  // How many supernodes each group holds: the two halves' and the separator's (with any that
  // mixes them). Tests check that a split matrix's work is in fact split.
  std::size_t supernodes_in(int group) const { return members_[group].size(); }
  // The analysis's elimination tree, which the low-rank correction walks too.
  const SupernodalTree& tree() const { return tree_; }

 private:
  // One thread's, made once per analysis: the matrix's values while a factorisation runs, the
  // row map and the dense block one descendant subtracts (CHOLMOD's maxcsize at most).
  struct Workspace {
    const double* values = nullptr;
    std::vector<int> position_in_supernode;  // per row: its place in the supernode being factored
    std::vector<double> update;
    int failed_column = -1;
  };
  void factor_group(int group, Workspace& work);
  void factor_supernode(int s, std::span<std::vector<int>* const> lists, std::vector<int>& relink, Workspace& work);
  bool halves_in_parallel(bool two_threads) const;
  // y ← L⁻¹ y over a group's supernodes, L's values `l` (double or single precision); what
  // they subtract from the separator's rows goes to `separator` (a half's) or straight into y
  // (the separator's own).
  template <typename Value>
  void forward_over(int group, const Value* l, double* y, double* separator) const;
  // y ← L⁻ᵀ y over a group's supernodes, children last.
  template <typename Value>
  void backward_over(int group, const Value* l, double* y) const;
  template <typename Value>
  void solve_forward_with(const Value* l, Eigen::VectorXd& v, bool two_threads) const;
  template <typename Value>
  void solve_backward_with(const Value* l, Eigen::VectorXd& v, bool two_threads) const;

  cholmod_factor* factor_;
  cholmod_common* common_;
  int n_;
  int nsuper_;
  const int* super_;  // per supernode: its first column (nsuper + 1)
  const int* pi_;     // per supernode: its first row index in rows_ (nsuper + 1)
  const int* px_;     // per supernode: its first value (nsuper + 1)
  const int* rows_;   // each supernode's row indices, its own columns first
  SupernodalTree tree_;
  std::vector<int> separator_columns_;  // the columns of the separator's supernodes
  std::vector<int> separator_slot_;     // per column: its place in separator_columns_, −1 if none
  mutable std::vector<double> separator_sums_[2];  // per half: its forward solve's terms there
  std::vector<int> members_[3];  // per group: its supernodes, ascending (children first)
  // The matrix's entries in the factor's layout: per supernode s, for k in
  // [entry_start_[s], entry_start_[s + 1]), the value upper.valuePtr()[entry_source_[k]] goes
  // to offset entry_target_[k] of s's block.
  std::vector<std::size_t> entry_start_;
  std::vector<int> entry_source_;
  std::vector<int> entry_target_;
  // Left-looking bookkeeping, per supernode d: the next supernode d updates is found in its
  // row list at next_row_[d]; the lists link d into that supernode's, one list per group.
  std::vector<int> next_row_;
  std::vector<int> next_in_list_;
  std::vector<int> head_[3];
  std::array<Workspace, 2> workspaces_;  // the halves', the first also the separator's
  // L̃, while the factor is kept in single precision: a block of CHOLMOD's (once the double
  // values'), given back to it.
  std::unique_ptr<float[], CholmodValues> single_;
};

}  // namespace hydrodda::numerics
