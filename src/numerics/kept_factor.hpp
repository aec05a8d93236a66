#pragma once
// A sparse Cholesky factor kept from one matrix to the next: factored once, then the
// preconditioner of conjugate gradients on later matrices of the same pattern, corrected by a
// low-rank term for the few parts that jumped where that pays, and factored afresh where it
// does not.
//
// The matrices are sums of parts, A = Σ_p A_p (an element's matrix, a spring, a storage term:
// whatever the caller sums), the factored one M = Σ_p M_p. A part's spread is the larger of
// λ_max and 1/λ_min of the pencil (A_p, M_p); the caller measures it from whatever changed (a
// permeability, a storage coefficient, a time step), and the plan reads nothing else.
//
// Bound (Saad, Iterative Methods, §6.11.3, with the outlying eigenvalues removed first;
// Axelsson and Lindskog, Numer. Math. 48, 1986): parts with spread ≤ c keep the eigenvalues
// of M⁻¹A in [1/c, c] (Rayleigh quotients of sums of semidefinite terms); each part outside
// moves at most rank(A_p) eigenvalues out. CG then needs at most
//   rank · #outside + log(ε/2) / log((c − 1)/(c + 1))
// iterations to cut the error by ε; with the parts outside taken into M exactly (a low-rank
// correction), the first term goes at the correction's cost. The plan is the cheapest over a
// ladder of c.

#include <array>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "numerics/sparse_cholesky.hpp"

namespace hydrodda::numerics {

// Past this many CG iterations on a kept factor, a fresh factorisation costs less than the
// drift does: the next solve factors afresh (the DDA's kept factors and the flow's alike).
inline constexpr int kRefactorAfterIterations = 6;

// What a plan weighs. No defaults: the costs are the caller's matrices' and machine's.
struct FactorReuseCosts {
  double tolerance;                   // ε, the error reduction CG must reach
  int max_iterations;                 // CG's budget on the kept factor
  int rank_per_part;                  // the largest rank of a part's change
  int max_corrected_parts;            // the most parts a correction takes
  double corrected_per_iteration;     // parts corrected at the cost of one CG iteration
  double iterations_saved_by_keeping; // what keeping the factor saves over a fresh one
};

inline constexpr int kNoReuseBound = std::numeric_limits<int>::max();

struct ReusePlan {
  std::vector<int> corrected;  // the parts taken exactly by a low-rank correction, ascending
  int bound = 0;               // the bound on CG's iterations that leaves (kNoReuseBound: none)
};

// The ladder of spreads c the plan tries.
inline constexpr std::array<double, 8> kReuseSpreads{1.001, 1.003, 1.01, 1.03, 1.1, 1.3, 2.0, 10.0};

// CG's iterations to cut the error by ε when every eigenvalue of M⁻¹A is in [1/c, c].
long chebyshev_iterations(double c, double tolerance);

// The cheapest of: the kept factor alone, or corrected for the parts outside one spread of the
// ladder. A correction is planned only when `correcting`, where the parts left let CG finish
// within max_iterations, and where it costs less than keeping the factor saves. `spreads`: one
// per part (NaN counts as outside every spread).
ReusePlan plan_factor_reuse(std::span<const double> spreads, bool correcting, const FactorReuseCosts& costs);

// z = M⁻¹ r for CG: the kept factor of `factor`, alone or corrected by a low-rank term. Valid
// while that factorisation stands.
class KeptFactorPreconditioner {
 public:
  explicit KeptFactorPreconditioner(SparseCholesky& factor) : factor_(factor) {}
  // The kept factor alone, which from here only preconditions (in lower precision where the
  // backend can: CG's iterations read half the memory).
  void use_factor_alone();
  // The kept factor corrected by `term`. False, and nothing changed, where the correction
  // cannot serve: the backend has none; the corrected matrix is singular to working precision;
  // or `term` downdates (a negative weight) a factor held in lower precision, whose rounding
  // would swamp what the downdate leaves (a part that lost 10⁷ of itself keeps 10⁻⁷, no more
  // than a float's rounding of the factor).
  bool use_corrected_factor(const LowRankTerm& term);
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  // Lets the correction go (its memory, before a fresh factorisation).
  void release() { corrected_.reset(); }

 private:
  SparseCholesky& factor_;
  std::unique_ptr<CorrectedFactor> corrected_;
};

}  // namespace hydrodda::numerics
