#pragma once
// The Sherman–Morrison–Woodbury correction of a kept Cholesky factor by a low-rank term
// (Hager, "Updating the inverse of a matrix", SIAM Review 31, 1989). With M = Pᵀ L Lᵀ P, the
// term's columns scaled, W = L⁻¹ P U |S|^½, and σ = sign S:
//   M + U S Uᵀ = Pᵀ L (I + W σ Wᵀ) Lᵀ P,
//   (M + U S Uᵀ)⁻¹ = Pᵀ L⁻ᵀ (I − W C⁻¹ Wᵀ) L⁻¹ P,   C = σ + Wᵀ W   (σ⁻¹ = σ).
// Each factor keeps W in its own sparse layout, a column's entries only on the path of its
// rows to the root of the elimination tree (the DDA's block factor, dda/factor_solver.cpp; the
// flow's supernodal factor, supernodal_correction.cpp), and sums σ + Wᵀ W from it; this
// is the small dense capacitance C both then factor and solve with.

#include <Eigen/Dense>

namespace hydrodda::numerics {

class WoodburyCapacitance {
 public:
  // Factors C = σ + Wᵀ W (by partial pivoting: C is symmetric but indefinite where σ has
  // downdates).
  // On one thread: past some 100 rows Eigen's blocked LU runs its products on OpenMP's threads
  // whatever the program's own thread count (numerics/parallel.hpp): with `--threads 1` on a
  // loaded host, and the DDA's block solver following 256 springs, 30% of a 1,601-block wall's
  // run was those threads and their barriers (docs/studies/2026-11-29-wall-open-close-passes.md).
  // Called from one thread at a time.
  void factor(const Eigen::MatrixXd& c) {
    const int threads = Eigen::nbThreads();
    Eigen::setNbThreads(1);
    lu_.compute(c);
    Eigen::setNbThreads(threads);
  }
  // Whether M + U S Uᵀ is singular to working precision: C's reciprocal condition number
  // estimate at most `smallest`.
  bool singular(double smallest) const { return !(lu_.rcond() > smallest); }
  // C⁻¹ t: applied to t = Wᵀ y, the coefficients of the columns of W that y ← y − W C⁻¹ Wᵀ y
  // subtracts.
  Eigen::VectorXd solve(const Eigen::VectorXd& t) const { return lu_.solve(t); }
  Eigen::Index size() const { return lu_.rows(); }

 private:
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace hydrodda::numerics
