#pragma once
// Steady Darcy flow in hydraulic head with P1 finite elements on a fixed triangle mesh: the
// system (darcy_assembly.hpp) solved by a sparse Cholesky factorisation, and the answer made
// into heads, pressures, fluxes and boundary flows (darcy_postprocessing.hpp).
// Built once per mesh and set of boundary conditions (numbering, sparsity pattern, symbolic
// factorisation); each solve() refills the matrix values in place and refactors numerically.
// solve_reusing_factor() keeps the last numeric factor instead, as the preconditioner of
// conjugate gradients on the new matrix, while it serves (docs/flow.md, "Coupling passes").

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "hydro/boundary_condition.hpp"
#include "hydro/darcy_assembly.hpp"
#include "hydro/flow_failure.hpp"
#include "hydro/flow_solution.hpp"
#include "hydro/fluid.hpp"
#include "hydro/linear_solver.hpp"
#include "hydro/permeability_field.hpp"
#include "mesh/triangle_mesh.hpp"
#include "numerics/kept_factor.hpp"

namespace hydrodda::hydro {

class DarcySolver {
 public:
  // Keeps a reference to `mesh`, which must outlive the solver. Throws std::runtime_error
  // when a condition names an unknown or empty boundary, or when nothing fixes the head
  // (SingularSystem when some connected part of the mesh has no fixed head).
  DarcySolver(const mesh::TriangleMesh& mesh, DarcyProblem problem,
              std::unique_ptr<numerics::SparseCholesky> solver = make_cholmod_solver());

  // Solves with an intrinsic permeability (m²) per triangle: isotropic scalars or tensors.
  // FlowSolveFailed, in the model's terms, when it cannot (here and in every solve below).
  FlowSolution solve(PermeabilityView permeability);

  // One backward-Euler step of S_s ∂h/∂t − ∇·(K ∇h) = 0 from `previous_heads` (one per node):
  // (A + Σ_e c_e M_e) h = f + Σ_e c_e M_e h_old, c_e = S_s,e/Δt (1/s, one per triangle), solved
  // directly with the same refinement as solve(), whose residual then counts the storage. The
  // matrix is factored again only when its values differ from the last step's (a new Δt or
  // permeability). The flow's storage_rate and balance_error count the water stored.
  FlowSolution solve_step(PermeabilityView permeability, std::span<const double> storage_over_step, MassMatrix kind,
                          std::span<const double> previous_heads);

  // New values for the same conditions (the same boundaries, kinds and order), e.g. a head
  // raised between coupling passes: the fixed nodes stay, so the pattern and its analysis are
  // kept. Throws std::invalid_argument when the conditions differ in anything but their values.
  void set_boundary_values(std::span<const BoundaryCondition> boundaries);
  const std::vector<BoundaryCondition>& boundary_conditions() const { return assembler_.problem().boundaries; }

  // Solves with a permeability, isotropic or a tensor, the factor of an earlier matrix serving as the
  // preconditioner of conjugate gradients on this one (Saad, Iterative Methods, alg. 9.1),
  // corrected for the few elements that jumped since where that pays (plan_preconditioning),
  // started from `start_heads` (one per node; empty: from zero). CG stops when the head error
  // it estimates, |M⁻¹ r|∞, is under kHeadTolerance of the heads' range and the mass balance
  // it estimates is a tenth of kBalanceTolerance; its answer is kept only when its mass
  // balance as reported (FlowSolution::balance_error) is at most kBalanceTolerance, else it
  // goes on once from the true residual, whose answer is kept within kBalanceBound (the
  // round-off of the heads, as in solve()'s). The matrix is factored afresh, and solved exactly as
  // by solve(), when no factor is kept; when the permeability has moved so far from the kept
  // factor's that CG could need more than kHopelessIterations (bound_iterations); when CG has
  // not got there in kMaxIterations (or will not, at the rate it goes); and at the solve
  // after one that needed more than kRefactorAfter iterations.
  FlowSolution solve_reusing_factor(PermeabilityView permeability, std::span<const double> start_heads);
  static constexpr double kHeadTolerance = 1e-13;
  static constexpr double kBalanceTolerance = 1e-12;
  static constexpr double kBalanceBound = 1e-10;  // the mass balance every solve meets
  static constexpr int kMaxIterations = 12;
  static constexpr int kRefactorAfter = numerics::kRefactorAfterIterations;
  static constexpr int kHopelessIterations = 3 * kMaxIterations;
  // At most this many elements whose permeability jumped since the kept factor (a fracture
  // opening or closing) are taken into the preconditioner exactly, by a low-rank correction of
  // the kept factor (numerics/supernodal_correction.hpp), rather than factoring afresh.
  static constexpr int kMaxCorrectedElements = 400;

  // A bound on the CG iterations solve_reusing_factor() would need with the kept factor, in
  // exact arithmetic, from how far each element's permeability is from the kept one (see
  // the .cpp); a large number when no factor is kept.
  int bound_iterations(PermeabilityView permeability) const;

  // The permeability whose factor solve_reusing_factor() would use next, as tensors (an
  // isotropic k as {k, 0, k}; empty: it will factor afresh). A checkpoint holds it;
  // restore_kept_factor() factors it again, so that a resumed run goes on with the very
  // factor, bit for bit, of the run it continues.
  std::vector<PermeabilityTensor> kept_factor_permeability() const { return kept_ ? kept_->tensors() : std::vector<PermeabilityTensor>{}; }
  // And whether that factor is held in single precision (it goes there in the first pass that
  // needs no correction of it: docs/flow.md). A checkpoint holds this too: a factor so held is
  // corrected only where elements open, so the next pass's path depends on it.
  bool kept_factor_in_single_precision() const { return kept_ && solver_->kept_for_preconditioning(); }
  void restore_kept_factor(std::span<const PermeabilityTensor> permeability, bool single_precision = false);
  // The same, shared rather than copied (null: none): a coupling pass holds the one it
  // started with and gives it back when it is abandoned, which factors it again only when
  // another has been factored since (or it went to single precision since).
  std::shared_ptr<const PermeabilityField> kept_factor() const { return kept_; }
  void restore_kept_factor(std::shared_ptr<const PermeabilityField> kept, bool single_precision = false);

  int unknown_count() const { return assembler_.unknown_count(); }
  long long stored_nonzeros() const { return assembler_.matrix().nonZeros(); }
  double reference_head() const { return assembler_.reference_head(); }
  // Still water standing at the lowest head the boundaries fix, h_s (the smallest fixed
  // head over the nodes: a head boundary's value, or z + p / ρg of a pressure boundary's node):
  // per node ρg (h_s − z) under the hydrostatic convention, ρg (h_s − h_ref) under the
  // overpressure one, which is 0 where h_s is h_ref (a head boundary the lowest). The state
  // the load ramp of the overpressure alone starts from (coupling/load_ramp.hpp).
  std::vector<double> still_water_pressure() const;
  // Seconds to build the pattern and analyse it.
  double setup_seconds() const { return setup_seconds_; }
  const std::string& solver_name() const { return solver_name_; }

 private:
  FlowSolution solve_with(PermeabilityView permeability);
  // solve_with(), keeping `permeability` as the factor's for the next solve_reusing_factor().
  FlowSolution solve_and_keep(PermeabilityView permeability);
  // Factorises the matrix assembled from `permeability` (FlowSolveFailed, in the model's terms,
  // when it cannot).
  void factorize_system(SolveTimings& timings, PermeabilityView permeability);
  // x = A⁻¹ f with the fresh factor, refined in extended precision (see solve_with).
  Eigen::VectorXd solve_directly(int& refinement_steps) const;
  // PCG with the kept factor, alone or corrected, from x (updated in place), `iterations` added
  // to; false when it gave up (x is then to be discarded).
  bool solve_by_conjugate_gradients(Eigen::VectorXd& x, int budget, int& iterations,
                                    const numerics::KeptFactorPreconditioner& preconditioner) const;
  // Per element, how far its permeability has moved from the kept factor's (see the .cpp).
  std::vector<double> element_spreads(PermeabilityView permeability) const;
  // The preconditioner of solve_reusing_factor(): the elements whose change since the kept
  // factor it takes exactly (none: the kept factor alone), and the bound on CG's iterations
  // that leaves (numerics::plan_factor_reuse).
  numerics::ReusePlan plan_preconditioning(PermeabilityView permeability, bool correcting) const;
  // K_e(k_e) − K_e(k⁰_e) of the given elements over the unknowns, as U S Uᵀ (two columns an
  // element at most, from the eigenvectors of the change of its conductivity tensor).
  LowRankTerm element_changes(std::span<const int> elements, PermeabilityView permeability) const;

  DarcyAssembler assembler_;
  std::unique_ptr<numerics::SparseCholesky> solver_;
  std::string solver_name_;
  double setup_seconds_ = 0.0;
  // The permeability whose factor solver_ holds, and the one offered for reuse: the same, or
  // null when the next solve is to factor afresh.
  std::shared_ptr<const PermeabilityField> factored_, kept_;
  // The values of the matrix solve_step() last factored; empty when the factor is another's.
  std::vector<double> step_matrix_values_;
};

}  // namespace hydrodda::hydro
