#pragma once
// Preconditioned conjugate gradients on a symmetric positive definite A x = b, the one CG of
// the program: the DDA solvers (to a relative residual, solve_by_conjugate_gradients) and the
// flow solver on its kept factor (to a head error and a mass balance of its own) run it, each
// with its own stopping rule.
//
// Pseudocode (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., alg. 9.1):
//   r = b − A x; z = M⁻¹ r; p = z
//   repeat: α = rᵀz / pᵀAp; x += α p; r −= α A p; z = M⁻¹ r; stop?
//           β = r'ᵀz' / rᵀz; p = z + β p

#include <functional>

#include <Eigen/Core>

namespace hydrodda::numerics {

// y = A x, or z = M⁻¹ r: the two operations conjugate gradients needs.
using VectorOperator = std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>;

// What a stopping rule says of an iterate.
enum class CgVerdict { go_on, converged, give_up };

// When CG stops; either part may be left empty (never stops there).
struct CgStoppingRule {
  // Asked of the residual r before it is preconditioned: where r alone decides, the last
  // application of M⁻¹ is saved.
  std::function<bool(const Eigen::VectorXd& r)> residual_converged;
  // Asked after z = M⁻¹ r, at iteration `iteration` (0: the start), x as it stands.
  std::function<CgVerdict(int iteration, const Eigen::VectorXd& r, const Eigen::VectorXd& z)> check;
};

// CG from x (updated in place) with r = b − A x given (updated in place), at most
// max_iterations iterations, each also added to `iterations`. Returns the iterations taken when
// the rule says converged; −1 when it gives up, when max_iterations pass first, or when CG
// breaks down (no descent left: A or M not positive definite in exact arithmetic any more).
int run_preconditioned_cg(const VectorOperator& multiply, const VectorOperator& precondition,
                          const CgStoppingRule& rule, int max_iterations, Eigen::VectorXd& x,
                          Eigen::VectorXd& r, long& iterations);

// CG on A x = b to ‖b − A x‖ ≤ tolerance ‖b‖, started from `guess` when it has b's size and
// leaves a smaller residual than zero does. Iterates on b/‖b‖, so that a load all but balanced
// (‖b‖ ~ 1e-150 at a static equilibrium) does not underflow the inner products. Returns the
// iterations taken (also added to `iterations`), or −1 as run_preconditioned_cg.
int solve_by_conjugate_gradients(const VectorOperator& multiply, const VectorOperator& precondition,
                                 const Eigen::VectorXd& b, const Eigen::VectorXd& guess, double tolerance,
                                 int max_iterations, Eigen::VectorXd& x, long& iterations);

}  // namespace hydrodda::numerics
