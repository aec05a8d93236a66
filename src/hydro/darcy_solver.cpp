#include "hydro/darcy_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "hydro/darcy_postprocessing.hpp"
#include "hydro/flow_failure.hpp"
#include "numerics/conjugate_gradients.hpp"
#include "numerics/kept_factor.hpp"

namespace hydrodda::hydro {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr int kMaxRefinementSteps = 4;
constexpr double kTargetBalance = 1e-14;  // relative mass balance that ends the refinement

}  // namespace

DarcySolver::DarcySolver(const mesh::TriangleMesh& mesh, DarcyProblem problem, std::unique_ptr<numerics::SparseCholesky> solver)
    : assembler_(mesh, std::move(problem)), solver_(std::move(solver)) {
  const auto start = Clock::now();
  if (!solver_) throw std::invalid_argument("DarcySolver needs a linear solver");
  solver_name_ = solver_->name();
  // The symbolic analysis (the fill-reducing ordering: seconds at a million triangles) runs
  // here, in line. Run on a thread of its own beside the rest of a coupled model's set-up, it
  // saved about a second at a million triangles but made the ordering, and so the heads at
  // round-off, differ from run to run of one scenario (44,653 nodes: 3.6e-15 at 136 of them),
  // which the contacts' states can carry to the answer.
  if (unknown_count() > 0) solver_->analyse(assembler_.matrix());
  setup_seconds_ = assembler_.setup_seconds() + seconds_since(start);
}

void DarcySolver::set_boundary_values(std::span<const BoundaryCondition> boundaries) {
  assembler_.set_boundary_values(boundaries);
}

FlowSolution DarcySolver::solve_and_keep(PermeabilityView permeability) {
  FlowSolution out = solve_with(permeability);
  factored_ = kept_ = std::make_shared<const PermeabilityField>(permeability);
  return out;
}

FlowSolution DarcySolver::solve(PermeabilityView permeability) {
  assembler_.check_size(permeability);
  return solve_and_keep(permeability);
}

void DarcySolver::factorize_system(SolveTimings& timings, PermeabilityView permeability) {
  const auto clock = Clock::now();
  step_matrix_values_.clear();
  try {
    solver_->factorize(assembler_.matrix());
  } catch (const SingularSystem&) {
    // The solver's own words are linear algebra's: the user is told what the model met.
    throw FlowSolveFailed(describe_flow_failure(assembler_.mesh(), permeability, assembler_.fixed_head(), "its matrix could not be factored"));
  }
  timings.factorize = seconds_since(clock);
}

Eigen::VectorXd DarcySolver::solve_directly(int& refinement_steps) const {
  Eigen::VectorXd x = solver_->solve(assembler_.rhs());
  double last_residual = INFINITY;
  // Iterative refinement with the residual in extended precision, x += A⁻¹(f − A x): the
  // contrast of fracture-like strips (1e5–1e6) makes the plain solve lose as many digits,
  // and the mass balance needs them back. One back-substitution and one product a step,
  // until the balance is 1e4 times inside its 1e-10 bound or the residual stops shrinking.
  for (int step = 0; step < kMaxRefinementSteps; ++step) {
    const DarcyAssembler::Residual residual = assembler_.compute_residual(x);
    const double r_norm = residual.r.lpNorm<Eigen::Infinity>();
    if (r_norm == 0.0 || residual.balance <= kTargetBalance || (step > 0 && r_norm >= 0.5 * last_residual))
      break;
    last_residual = r_norm;
    x += solver_->solve(residual.r);
    ++refinement_steps;
  }
  return x;
}

FlowSolution DarcySolver::solve_with(PermeabilityView permeability) {
  SolveTimings timings;
  auto clock = Clock::now();
  assembler_.assemble(permeability);
  timings.assemble = seconds_since(clock);

  Eigen::VectorXd x(unknown_count());
  int refinement_steps = 0;
  if (unknown_count() > 0) {
    factorize_system(timings, permeability);
    clock = Clock::now();
    x = solve_directly(refinement_steps);
    if (!x.allFinite())
      throw FlowSolveFailed(describe_flow_failure(assembler_.mesh(), permeability, assembler_.fixed_head(), "its heads came out not finite"));
    timings.solve = seconds_since(clock);
  }
  clock = Clock::now();
  FlowSolution out = make_flow_solution(assembler_, x, permeability);
  timings.postprocess = seconds_since(clock);
  out.timings = timings;
  out.refinement_steps = refinement_steps;
  return out;
}

FlowSolution DarcySolver::solve_step(PermeabilityView permeability, std::span<const double> storage_over_step,
                                     MassMatrix kind, std::span<const double> previous_heads) {
  assembler_.check_size(permeability);
  SolveTimings timings;
  auto clock = Clock::now();
  assembler_.assemble(permeability);
  assembler_.add_storage(storage_over_step, kind, previous_heads);
  timings.assemble = seconds_since(clock);
  Eigen::VectorXd x(unknown_count());
  int refinement_steps = 0;
  bool factorised = false;
  if (unknown_count() > 0) {
    const SparseMatrix& a = assembler_.matrix();
    const std::span<const double> values(a.valuePtr(), static_cast<std::size_t>(a.nonZeros()));
    if (!std::equal(values.begin(), values.end(), step_matrix_values_.begin(), step_matrix_values_.end())) {
      factorize_system(timings, permeability);
      step_matrix_values_.assign(values.begin(), values.end());
      factorised = true;
    }
    clock = Clock::now();
    x = solve_directly(refinement_steps);
    if (!x.allFinite())
      throw FlowSolveFailed(describe_flow_failure(assembler_.mesh(), permeability, assembler_.fixed_head(), "its heads came out not finite"));
    timings.solve = seconds_since(clock);
  }
  // The factor holds storage: it is no permeability's alone, so none is kept for reuse.
  factored_ = kept_ = nullptr;
  clock = Clock::now();
  FlowSolution out = make_flow_solution(assembler_, x, permeability);
  timings.postprocess = seconds_since(clock);
  out.timings = timings;
  out.refinement_steps = refinement_steps;
  out.factorised = factorised;
  return out;
}

FlowSolution DarcySolver::solve_reusing_factor(PermeabilityView permeability, std::span<const double> start_heads) {
  assembler_.check_size(permeability);
  if (!start_heads.empty() && start_heads.size() != assembler_.mesh().nodes.size())
    throw std::invalid_argument("flow: the starting heads must be one per node");
  if (unknown_count() == 0) return solve_and_keep(permeability);
  numerics::ReusePlan plan = plan_preconditioning(permeability, true);
  if (plan.bound > kHopelessIterations) return solve_and_keep(permeability);

  SolveTimings timings;
  auto clock = Clock::now();
  assembler_.assemble(permeability);
  timings.assemble = seconds_since(clock);
  clock = Clock::now();
  // The elements that jumped, taken exactly by a low-rank correction of the kept factor; where
  // that cannot serve (numerics::KeptFactorPreconditioner::use_corrected_factor), the kept
  // factor alone if it will do. Without a correction the kept factor only preconditions from
  // here, in single precision where the solver can: CG's iterations read half the memory, and
  // the factor holds half while the blocks move. (A downdate of such a factor, made in
  // bench_hydro's LatePassFlow/10/1/60, left CG too slow for every other pass, which factored
  // afresh.)
  numerics::KeptFactorPreconditioner preconditioner(*solver_);
  if (plan.corrected.empty()) {
    preconditioner.use_factor_alone();
  } else if (!preconditioner.use_corrected_factor(element_changes(plan.corrected, permeability))) {
    plan = plan_preconditioning(permeability, false);
    if (plan.bound > kHopelessIterations) {
      FlowSolution out = solve_and_keep(permeability);
      out.timings.assemble += timings.assemble;
      return out;
    }
  }
  timings.factorize = seconds_since(clock);
  clock = Clock::now();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(unknown_count());
  if (!start_heads.empty())
    for (int u = 0; u < unknown_count(); ++u) x[u] = start_heads[assembler_.free_nodes()[u]];
  // CG until its estimates of the head error and of the mass balance are inside their
  // tolerances, then the balance as reported; once more from the true residual if that is
  // not there yet (the recurrence's residual drifts from the true one by round-off), within
  // the one budget of iterations. Converged again from the true residual, the heads are
  // within kHeadTolerance of the exact ones and what is left of the balance is the round-off
  // of the heads themselves, as in the exact solve's: where a joint crosses a head boundary
  // obliquely, flow enters and leaves by that boundary, and the net flow the balance is
  // relative to is tens of times smaller than the nodal flows whose round-off it carries
  // (FactorReuse.JointTensorsSolveOnTheKeptFactorToTheExactHeads: 2e-12 to 1e-11, exact
  // solve and CG alike). That answer is kept within kBalanceBound, as every solve's is.
  int taken = 0;
  FlowSolution out;
  for (int round = 0; round < 2; ++round) {
    if (!solve_by_conjugate_gradients(x, kMaxIterations - taken, taken, preconditioner)) break;
    timings.solve = seconds_since(clock);
    clock = Clock::now();
    out = make_flow_solution(assembler_, x, permeability);
    timings.postprocess += seconds_since(clock);
    clock = Clock::now();
    if (out.balance_error <= (round == 0 ? kBalanceTolerance : kBalanceBound)) {
      out.timings = timings;
      out.factorised = false;
      out.cg_iterations = taken;
      out.corrected_elements = static_cast<int>(plan.corrected.size());
      // Drifted far enough that CG costs more than it saves: a fresh factor next time.
      if (taken > kRefactorAfter) kept_.reset();
      return out;
    }
  }
  // CG did not get there: factor afresh and solve exactly, as solve() does (its answer and the
  // correction let go first: at a million triangles the answer is 30 MB beside the
  // factorisation).
  out = {};
  preconditioner.release();
  out = solve_and_keep(permeability);
  out.timings.assemble += timings.assemble;
  out.cg_iterations = taken;
  return out;
}

namespace {

// Two costs the plan weighs (numerics::plan_factor_reuse), tuned on one machine at 10^6
// triangles and kept as tuned, since which passes factor afresh shows in the heads at
// round-off (their measurements: docs/flow.md, "Fractures that open or close").
// How many elements corrected exactly cost about one CG iteration: the half-solves along
// their paths up the elimination tree, and the iterations CG adds where they closed. Larger:
// more elements corrected, fewer fresh factors, and longer corrections applied at every
// iteration.
constexpr double kCorrectedPerIteration = 80.0;
// What keeping the factor saves over a fresh one, in iterations: a correction that costs more
// is not made. Larger: corrections made where a fresh factor would be cheaper; smaller: fresh
// factors where a corrected one would do.
constexpr double kIterationsSavedByKeeping = 1.0;

// The plan's weights for the flow matrix: an element's change has rank two (its conductance
// matrix is area Bᵀ K B, B 2 × 3).
constexpr numerics::FactorReuseCosts kReuseCosts{DarcySolver::kHeadTolerance, DarcySolver::kMaxIterations, 2,
                                                 DarcySolver::kMaxCorrectedElements, kCorrectedPerIteration,
                                                 kIterationsSavedByKeeping};

// An element's spread: the larger of λ_max and 1/λ_min of the pencil (k, k⁰).
double spread_of(const PermeabilityTensor& k, const PermeabilityTensor& k0) {
  double lo = 0.0, hi = 0.0;
  if (k.xy == 0.0 && k0.xy == 0.0) {  // diagonal pencil: exact ratios
    lo = std::min(k.xx / k0.xx, k.yy / k0.yy);
    hi = std::max(k.xx / k0.xx, k.yy / k0.yy);
  } else {
    const double a = k0.xx * k0.yy - k0.xy * k0.xy;
    const double b = k0.xx * k.yy + k0.yy * k.xx - 2.0 * k0.xy * k.xy;
    const double c = k.xx * k.yy - k.xy * k.xy;
    const double root = std::sqrt(std::max(b * b - 4.0 * a * c, 0.0));
    hi = (b + root) / (2.0 * a);
    lo = c / (a * hi);  // λ_min λ_max = det k / det k⁰, without the cancellation of b − root
  }
  return std::max(hi, 1.0 / lo);
}

}  // namespace

// The kept factor is M = Σ_e K_e(k⁰_e), the new matrix A = Σ_e K_e(k_e), with
// K_e(k) = area_e Bᵀ k B the element matrix of a permeability tensor k (B the shape
// gradients). For any x, with g = B x, xᵀK_e(k)x / xᵀK_e(k⁰)x = gᵀ k g / gᵀ k⁰ g lies between
// the generalised eigenvalues of the pencil (k, k⁰), the roots λ of det(k − λ k⁰) = 0:
//   λ² det k⁰ − λ (k⁰xx kyy + k⁰yy kxx − 2 k⁰xy kxy) + det k = 0;
// for isotropic or axis-aligned tensors simply kxx/k⁰xx and kyy/k⁰yy: each element's spread,
// from which numerics::plan_factor_reuse bounds CG's iterations (numerics/kept_factor.hpp),
// with ε = kHeadTolerance. A storage term would enter each element's pencil alike.
std::vector<double> DarcySolver::element_spreads(PermeabilityView permeability) const {
  std::vector<double> spreads(permeability.size());
  const PermeabilityView kept = kept_->view();
  for (std::size_t e = 0; e < permeability.size(); ++e) spreads[e] = spread_of(permeability[e], kept[e]);
  return spreads;
}

int DarcySolver::bound_iterations(PermeabilityView permeability) const {
  return plan_preconditioning(permeability, false).bound;
}

// Where a whole fracture network drifts by several per cent a pass, or hundreds of elements
// jump, a fresh factor is the cheaper.
numerics::ReusePlan DarcySolver::plan_preconditioning(PermeabilityView permeability, bool correcting) const {
  if (!kept_ || kept_->size() != permeability.size()) return {{}, numerics::kNoReuseBound};
  return numerics::plan_factor_reuse(element_spreads(permeability), correcting, kReuseCosts);
}

// K_e(k) − K_e(k⁰) = area_e Bᵀ (K − K⁰) B, K the conductivity; with the change of the tensor
// K − K⁰ = Σ λ_i v_i v_iᵀ (its eigenpairs), = Σ λ_i area_e (Bᵀ v_i)(Bᵀ v_i)ᵀ: a column Bᵀ v_i
// (∇φ_j · v_i at each free corner j) and a weight λ_i area_e for each nonzero λ_i.
LowRankTerm DarcySolver::element_changes(std::span<const int> elements, PermeabilityView permeability) const {
  LowRankTerm term;
  const PermeabilityView kept = kept_->view();
  const double factor = assembler_.problem().fluid.conductivity_per_permeability();
  const mesh::TriangleMesh& fluid_mesh = assembler_.mesh();
  for (int e : elements) {
    const PermeabilityTensor k = permeability[e], k0 = kept[e];
    const double dxx = (k.xx - k0.xx) * factor, dxy = (k.xy - k0.xy) * factor, dyy = (k.yy - k0.yy) * factor;
    std::array<std::pair<double, geometry::Point>, 2> modes;
    if (dxy == 0.0) {
      modes = {{{dxx, {1.0, 0.0}}, {dyy, {0.0, 1.0}}}};
    } else {  // the eigenpairs of [[dxx, dxy], [dxy, dyy]]
      const double mean = 0.5 * (dxx + dyy), radius = std::hypot(0.5 * (dxx - dyy), dxy);
      const double l1 = mean + radius, l2 = mean - radius;
      const geometry::Point v1 = geometry::Point{dxy, l1 - dxx} * (1.0 / std::hypot(dxy, l1 - dxx));
      modes = {{{l1, v1}, {l2, {-v1.y, v1.x}}}};
    }
    const auto& tri = fluid_mesh.triangles[e];
    const double area = std::abs(mesh::triangle_area(fluid_mesh, e));
    const auto g = compute_shape_gradients(fluid_mesh.nodes[tri[0]], fluid_mesh.nodes[tri[1]], fluid_mesh.nodes[tri[2]]);
    for (const auto& [lambda, v] : modes) {
      if (lambda == 0.0) continue;
      const std::size_t before = term.row.size();
      for (int i = 0; i < 3; ++i) {
        const int u = assembler_.unknown_of_node()[tri[i]];
        const double value = g[i].x * v.x + g[i].y * v.y;
        if (u < 0 || value == 0.0) continue;
        term.row.push_back(u);
        term.value.push_back(value);
      }
      if (term.row.size() == before) continue;
      term.weight.push_back(lambda * area);
      term.start.push_back(static_cast<int>(term.row.size()));
    }
  }
  return term;
}

void DarcySolver::restore_kept_factor(std::span<const PermeabilityTensor> permeability, bool single_precision) {
  restore_kept_factor(permeability.empty() ? nullptr : std::make_shared<const PermeabilityField>(permeability),
                      single_precision);
}

void DarcySolver::restore_kept_factor(std::shared_ptr<const PermeabilityField> kept, bool single_precision) {
  // The factor solver_ holds is already this one's, and in double or in the single precision
  // asked: nothing to factor. A factor in single precision cannot go back to double.
  const bool held = kept && kept == factored_ && (single_precision || !solver_->kept_for_preconditioning());
  if (kept && !held) {
    assembler_.check_size(kept->view());
    assembler_.assemble(kept->view());
    SolveTimings timings;
    if (unknown_count() > 0) factorize_system(timings, kept->view());
    factored_ = kept;
  }
  kept_ = std::move(kept);
  if (kept_ && single_precision && unknown_count() > 0) solver_->keep_for_preconditioning();
}

std::vector<double> DarcySolver::still_water_pressure() const {
  const double datum = assembler_.fixed_head_range()[0];
  const DarcyProblem& problem = assembler_.problem();
  const mesh::TriangleMesh& mesh = assembler_.mesh();
  const double rho_g = problem.fluid.unit_weight();
  std::vector<double> pressure(mesh.nodes.size());
  for (std::size_t v = 0; v < pressure.size(); ++v)
    pressure[v] = problem.pressure == PressureConvention::overpressure ? rho_g * (datum - assembler_.reference_head())
                                                                       : rho_g * (datum - mesh.nodes[v].y);
  return pressure;
}

// Preconditioned CG (numerics/conjugate_gradients.hpp), M the kept factor, stopped here when
// |z|∞ ≤ kHeadTolerance · range(h), z = M⁻¹ r being the error A⁻¹ r as far as M is A; and
// |Σ r| ≤ kBalanceTolerance / 10 of the boundary flow at the start, Σ r being what the boundary
// flows fail to balance by (compute_boundary_flows). Gives up past `budget` iterations, as soon
// as the rate so far says the budget will not do, or when CG breaks down.
bool DarcySolver::solve_by_conjugate_gradients(Eigen::VectorXd& x, int budget, int& iterations,
                                               const numerics::KeptFactorPreconditioner& preconditioner) const {
  const auto multiply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) {
    y = assembler_.matrix().selfadjointView<Eigen::Upper>() * v;
  };
  const auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd& z) { preconditioner.apply(v, z); };
  // The heads' range, fixed ones included: the scale of the head error that counts.
  const auto head_tolerance = [&] {
    const auto [lowest_fixed, highest_fixed] = assembler_.fixed_head_range();
    const double lo = std::min(x.minCoeff(), lowest_fixed), hi = std::max(x.maxCoeff(), highest_fixed);
    const double scale = hi > lo ? hi - lo : std::max({std::abs(lo), std::abs(hi), 1e-300});
    return kHeadTolerance * scale;
  };
  // The starting residual in extended precision, as the refinement takes it.
  const DarcyAssembler::Residual start = assembler_.compute_residual(x);
  // Relative to the smaller of the nodal and the net boundary flow: where flow enters and
  // leaves by one boundary (a joint crossing it obliquely), the net flow that the reported
  // balance is relative to is the smaller.
  const double balance_tolerance = 0.1 * kBalanceTolerance * std::min(start.boundary, start.net);
  Eigen::VectorXd r = start.r;
  double first_error = 0.0;
  const auto check = [&](int it, const Eigen::VectorXd& residual, const Eigen::VectorXd& z) {
    const double error = z.lpNorm<Eigen::Infinity>();
    if (it == 0) first_error = error;
    if (error <= head_tolerance() && std::abs(residual.sum()) <= balance_tolerance) return numerics::CgVerdict::converged;
    // At the mean rate so far CG would need more than the budget: give up now rather than
    // at its end (a fracture that opened or closed changed the matrix too much for the old
    // factor). Not before four iterations: CG often starts slowly, then speeds up.
    if (it >= 4) {
      const double rate = std::pow(error / first_error, 1.0 / it);
      if (!(rate < 1.0) || it + std::log(head_tolerance() / error) / std::log(rate) > budget)
        return numerics::CgVerdict::give_up;
    }
    return numerics::CgVerdict::go_on;
  };
  long taken = iterations;
  const int result = numerics::run_preconditioned_cg(multiply, precondition, {{}, check}, budget, x, r, taken);
  iterations = static_cast<int>(taken);
  return result >= 0;
}

}  // namespace hydrodda::hydro
