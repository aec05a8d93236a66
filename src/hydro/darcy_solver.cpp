#include "hydro/darcy_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/parallel.hpp"
#include "hydro/flow_failure.hpp"
#include "numerics/conjugate_gradients.hpp"

namespace hydrodda::hydro {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr int kMaxRefinementSteps = 4;
constexpr double kTargetBalance = 1e-14;  // relative mass balance that ends the refinement
// The three node pairs of a triangle whose couplings K_e(i, j), i ≠ j, are kept.
constexpr std::array<std::array<int, 2>, 3> kEdgePairs{{{0, 1}, {0, 2}, {1, 2}}};
// The six local pairs (i, j) whose values enter the upper triangle, at (row, column) =
// (min, max) of their unknowns.
constexpr std::array<std::array<int, 2>, 6> kLocalPairs{{{0, 0}, {1, 1}, {2, 2}, {1, 0}, {2, 0}, {2, 1}}};

// K = k ρ_w g / μ.
Conductivity conductivity(const PermeabilityTensor& k, double factor) {
  return {k.xx * factor, k.xy * factor, k.yy * factor};
}

}  // namespace

double FlowSolution::boundary_flow(const std::string& name) const {
  for (const BoundaryFlow& b : boundary_flows)
    if (b.name == name) return b.flow;
  throw std::runtime_error("flow solution has no boundary named '" + name + "'");
}

double FlowSolution::total_inflow() const {
  double inflow = 0.0;
  for (const BoundaryFlow& b : boundary_flows) inflow += std::max(-b.flow, 0.0);
  return inflow;
}

DarcySolver::DarcySolver(const mesh::TriangleMesh& mesh, DarcyProblem problem,
                         std::unique_ptr<LinearSolver> solver)
    : mesh_(mesh), problem_(std::move(problem)), solver_(std::move(solver)) {
  const auto start = Clock::now();
  if (!solver_) throw std::invalid_argument("DarcySolver needs a linear solver");
  solver_name_ = solver_->name();
  if (!(problem_.fluid.density > 0.0) || !(problem_.fluid.viscosity > 0.0) ||
      !(problem_.fluid.gravity > 0.0))
    throw std::runtime_error("fluid density, viscosity and gravity must be positive");
  mesh::validate(mesh_);
  setup_boundary_conditions();
  setup_pattern();
  setup_seconds_ += seconds_since(start);
}

void DarcySolver::set_boundary_values(std::span<const BoundaryCondition> boundaries) {
  const auto same_condition = [](const BoundaryCondition& a, const BoundaryCondition& b) {
    return a.boundary == b.boundary && a.kind == b.kind;
  };
  if (!std::equal(boundaries.begin(), boundaries.end(), problem_.boundaries.begin(), problem_.boundaries.end(),
                  same_condition))
    throw std::invalid_argument(
        "flow: only the values of the boundary conditions may change, not which boundaries they name or "
        "their kind");
  const std::vector<int> free_before = free_nodes_;
  const std::vector<BoundaryCondition> before = problem_.boundaries;
  problem_.boundaries.assign(boundaries.begin(), boundaries.end());
  try {
    setup_boundary_conditions();
  } catch (...) {
    problem_.boundaries = before;
    setup_boundary_conditions();
    throw;
  }
  // The same conditions on the same edges fix the same nodes.
  if (free_nodes_ != free_before) throw std::logic_error("flow: new boundary values changed the fixed nodes");
}

void DarcySolver::setup_boundary_conditions() {
  const int node_count = mesh_.node_count();
  const double rho_g = problem_.fluid.unit_weight();
  std::vector<const BoundaryCondition*> condition_of(mesh_.boundary_names.size(), nullptr);
  for (const BoundaryCondition& bc : problem_.boundaries) {
    const int b = mesh::find_boundary(mesh_, bc.boundary);
    if (b < 0) throw std::runtime_error("flow boundary condition on '" + bc.boundary +
                                        "', which is not a boundary of the mesh");
    if (!std::isfinite(bc.value))
      throw std::runtime_error("flow boundary condition on '" + bc.boundary + "' is not finite");
    if (condition_of[b]) throw std::runtime_error("two flow boundary conditions on '" + bc.boundary + "'");
    condition_of[b] = &bc;
    const bool has_edges = std::any_of(mesh_.boundary_edges.begin(), mesh_.boundary_edges.end(),
                                       [&](const mesh::BoundaryEdge& e) { return e.boundary == b; });
    if (!has_edges) throw std::runtime_error("flow boundary '" + bc.boundary + "' has no mesh edges");
  }
  // h_ref: the smallest fixed-head value (0 when no head is fixed directly).
  reference_head_ = 0.0;
  bool any_head = false;
  for (const BoundaryCondition& bc : problem_.boundaries)
    if (bc.kind == BoundaryKind::head) {
      reference_head_ = any_head ? std::min(reference_head_, bc.value) : bc.value;
      any_head = true;
    }

  fixed_head_.assign(node_count, std::numeric_limits<double>::quiet_NaN());
  neumann_outflow_.assign(node_count, 0.0);
  prescribed_flow_.assign(mesh_.boundary_names.size(), 0.0);
  std::vector<FixedShare> shares;
  for (const mesh::BoundaryEdge& e : mesh_.boundary_edges) {
    if (e.boundary < 0 || !condition_of[e.boundary]) continue;  // no-flow
    const BoundaryCondition& bc = *condition_of[e.boundary];
    const double length = geometry::distance(mesh_.nodes[e.nodes[0]], mesh_.nodes[e.nodes[1]]);
    if (bc.kind == BoundaryKind::flux) {
      // ∫_edge φ_i q_N ds = q_N L / 2 for each end node.
      for (int v : e.nodes) neumann_outflow_[v] += 0.5 * bc.value * length;
      prescribed_flow_[e.boundary] += bc.value * length;
      continue;
    }
    for (int v : e.nodes) {
      const double h = bc.kind == BoundaryKind::head ? bc.value
                       : problem_.pressure == PressureConvention::overpressure
                           ? reference_head_ + bc.value / rho_g   // p = ρg (h − h_ref)
                           : mesh_.nodes[v].y + bc.value / rho_g; // p = ρg (h − z)
      fixed_head_[v] = h;  // where two fixed boundaries meet, the later edge's value stands
      shares.push_back({v, e.boundary, 0.5 * length});
    }
  }
  // Each fixed node's reaction is shared among its fixed boundaries by edge length.
  std::sort(shares.begin(), shares.end(), [](const FixedShare& a, const FixedShare& b) {
    return a.node != b.node ? a.node < b.node : a.boundary < b.boundary;
  });
  fixed_shares_.clear();
  for (std::size_t i = 0; i < shares.size();) {
    std::size_t j = i;
    double total = 0.0;
    while (j < shares.size() && shares[j].node == shares[i].node) total += shares[j++].weight;
    for (std::size_t k = i; k < j; ++k) {
      if (!fixed_shares_.empty() && fixed_shares_.back().node == shares[k].node &&
          fixed_shares_.back().boundary == shares[k].boundary)
        fixed_shares_.back().weight += shares[k].weight / total;
      else
        fixed_shares_.push_back({shares[k].node, shares[k].boundary, shares[k].weight / total});
    }
    i = j;
  }
  if (fixed_shares_.empty())
    throw std::runtime_error(
        "flow: nothing fixes the head (give a head or pressure condition on at least one "
        "named boundary); the problem has no unique solution");

  check_every_part_is_fixed();
  fixed_head_range_ = {INFINITY, -INFINITY};
  for (double h : fixed_head_)
    if (!std::isnan(h)) fixed_head_range_ = {std::min(fixed_head_range_[0], h), std::max(fixed_head_range_[1], h)};
  unknown_of_node_.assign(node_count, -1);
  free_nodes_.clear();
  for (int v = 0; v < node_count; ++v)
    if (std::isnan(fixed_head_[v])) {
      unknown_of_node_[v] = static_cast<int>(free_nodes_.size());
      free_nodes_.push_back(v);
    }
}

// A part of the mesh that touches no fixed node has no unique head (the matrix is singular
// there, though a factorisation may only see a tiny pivot): find the parts with a
// union–find over the triangles' nodes and refuse any part without a fixed node.
void DarcySolver::check_every_part_is_fixed() const {
  std::vector<int> parent(mesh_.nodes.size());
  for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& tri : mesh_.triangles)
    for (int k = 1; k < 3; ++k) {
      const int a = find(tri[0]), b = find(tri[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<char> fixed_part(mesh_.nodes.size(), 0), used(mesh_.nodes.size(), 0);
  for (int v = 0; v < mesh_.node_count(); ++v)
    if (!std::isnan(fixed_head_[v])) fixed_part[find(v)] = 1;
  for (const auto& tri : mesh_.triangles)
    for (int v : tri) used[v] = 1;
  for (int v = 0; v < mesh_.node_count(); ++v)
    if (used[v] && !fixed_part[find(v)])
      throw SingularSystem("flow: the part of the mesh around node " + std::to_string(v) + " (" +
                           std::to_string(mesh_.nodes[v].x) + ", " + std::to_string(mesh_.nodes[v].y) +
                           ") touches no fixed-head boundary, so its head is undetermined");
}

void DarcySolver::setup_pattern() {
  const int n = unknown_count();
  const int triangles = mesh_.triangle_count();
  // Upper-triangle (column, row) pairs of every element, bucketed by column (a counting
  // sort), each column's rows ordered and made unique: the CSC pattern, in linear time (sorting
  // all 6 T pairs took a quarter of a second at a million triangles). Hand-written: the
  // pattern is built once, values are refilled in place after.
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);
  fixed_elements_.clear();
  for (int t = 0; t < triangles; ++t) {
    const auto& tri = mesh_.triangles[t];
    bool has_fixed = false;
    for (const auto& [i, j] : kLocalPairs) {
      const int a = unknown_of_node_[tri[i]], b = unknown_of_node_[tri[j]];
      if (a < 0 || b < 0) {
        has_fixed = true;
        continue;
      }
      ++start[std::max(a, b) + 1];
    }
    if (has_fixed) fixed_elements_.push_back(t);
  }
  for (int c = 0; c < n; ++c) start[c + 1] += start[c];
  std::vector<int> rows(static_cast<std::size_t>(start[n]));
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (const auto& tri : mesh_.triangles)
      for (const auto& [i, j] : kLocalPairs) {
        const int a = unknown_of_node_[tri[i]], b = unknown_of_node_[tri[j]];
        if (a >= 0 && b >= 0) rows[next[std::max(a, b)]++] = std::min(a, b);
      }
  }
  // Each column holds a dozen rows or so: insertion sort, then the distinct ones moved down
  // in place (a column never ends past where it began).
  std::size_t nonzeros = 0;
  std::vector<int> column_start(static_cast<std::size_t>(n) + 1, 0);
  for (int c = 0; c < n; ++c) {
    int* const first = rows.data() + start[c];
    int* const last = rows.data() + start[c + 1];
    for (int* i = first; i != last; ++i)
      for (int* j = i; j != first && *(j - 1) > *j; --j) std::swap(*(j - 1), *j);
    column_start[c] = static_cast<int>(nonzeros);
    for (int* i = first; i != last; ++i)
      if (i == first || *i != *(i - 1)) rows[nonzeros++] = *i;
  }
  column_start[n] = static_cast<int>(nonzeros);

  matrix_.resize(n, n);
  matrix_.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  std::copy(column_start.begin(), column_start.end(), outer);
  std::copy(rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(nonzeros), inner);
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + nonzeros, 0.0);
  std::vector<int>().swap(rows);

  // The off-diagonal pairs' positions; a diagonal entry is the last of its column (rows ascend
  // and none lies below the diagonal), found from the column itself.
  entry_.assign(3 * static_cast<std::size_t>(triangles), -1);
  for (int t = 0; t < triangles; ++t) {
    const auto& tri = mesh_.triangles[t];
    for (int p = 3; p < 6; ++p) {
      const int a = unknown_of_node_[tri[kLocalPairs[p][0]]], b = unknown_of_node_[tri[kLocalPairs[p][1]]];
      if (a < 0 || b < 0) continue;
      const int col = std::max(a, b), row = std::min(a, b);
      const int* first = inner + outer[col];
      const int* last = inner + outer[col + 1];
      entry_[3 * static_cast<std::size_t>(t) + (p - 3)] = static_cast<int>(std::lower_bound(first, last, row) - inner);
    }
  }
  rhs_.resize(n);
  // The symbolic analysis (the fill-reducing ordering: seconds at a million triangles) runs
  // here, in line. Run on a thread of its own beside the rest of a coupled model's set-up, it
  // saved about a second at a million triangles but made the ordering, and so the heads at
  // round-off, differ from run to run of one scenario (44,653 nodes: 3.6e-15 at 136 of them),
  // which the contacts' states can carry to the answer.
  if (n > 0) solver_->analyse(matrix_);
}

double DarcySolver::setup_seconds() const { return setup_seconds_; }

void DarcySolver::assemble_system(PermeabilityView permeability) {
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
  // Right-hand side: f_i = −∫ φ_i q_N ds (a prescribed outflow removes water at i) ...
  for (int u = 0; u < unknown_count(); ++u) rhs_[u] = -neumann_outflow_[free_nodes_[u]];
  double* values = matrix_.valuePtr();
  const int* outer = matrix_.outerIndexPtr();
  element_coupling_.resize(3 * mesh_.triangles.size());
  const double factor = problem_.fluid.conductivity_per_permeability();
  for (int t = 0; t < mesh_.triangle_count(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const auto ke = compute_element_matrix(mesh_.nodes[tri[0]], mesh_.nodes[tri[1]],
                                           mesh_.nodes[tri[2]], conductivity(permeability[t], factor));
    double* coupling = &element_coupling_[3 * static_cast<std::size_t>(t)];
    for (int p = 0; p < 3; ++p) coupling[p] = ke[kEdgePairs[p][0]][kEdgePairs[p][1]];
    for (int i = 0; i < 3; ++i) {
      const int u = unknown_of_node_[tri[i]];
      if (u >= 0) values[outer[u + 1] - 1] += ke[i][i];
    }
    const int* entry = &entry_[3 * static_cast<std::size_t>(t)];
    for (int p = 3; p < 6; ++p)
      if (entry[p - 3] >= 0) values[entry[p - 3]] += ke[kLocalPairs[p][0]][kLocalPairs[p][1]];
  }
  // ... minus the fixed heads carried over to the unknowns: f_i −= K_ij h_j, j fixed.
  for (int t : fixed_elements_) {
    const auto& tri = mesh_.triangles[t];
    const auto ke = compute_element_matrix(mesh_.nodes[tri[0]], mesh_.nodes[tri[1]],
                                           mesh_.nodes[tri[2]], conductivity(permeability[t], factor));
    for (int i = 0; i < 3; ++i) {
      const int u = unknown_of_node_[tri[i]];
      if (u < 0) continue;
      for (int j = 0; j < 3; ++j)
        if (unknown_of_node_[tri[j]] < 0) rhs_[u] -= ke[i][j] * fixed_head_[tri[j]];
    }
  }
}

// (A h)_i for every node, from the element matrices kept by assemble_system, in the
// pairwise form (A h)_i = Σ_e Σ_{j≠i} K_e(i, j) (h_j − h_i) (rows of K_e sum to zero). Each
// pair enters node i and node j with opposite signs, bit for bit, so Σ_i (A h)_i = 0 to the
// long-double accumulation: the boundary flows then balance to round-off whatever the
// contrast, and the residual that drives the iterative refinement is the same one.
// On two threads each takes the nodes of one half of the numbering and adds, for them only, the
// same terms in the same order as one thread does: the sums are the same, bit for bit.
std::vector<long double> DarcySolver::compute_a_times_h(const std::vector<double>& h) const {
  std::vector<long double> ah(h.size(), 0.0L);
  const int nodes = static_cast<int>(h.size());
  const auto add_for_nodes = [&](int first, int last) {
    for (int t = 0; t < mesh_.triangle_count(); ++t) {
      const auto& tri = mesh_.triangles[t];
      const double* k = &element_coupling_[3 * static_cast<std::size_t>(t)];
      for (int p = 0; p < 3; ++p) {
        const int i = tri[kEdgePairs[p][0]], j = tri[kEdgePairs[p][1]];
        const long double flow = static_cast<long double>(k[p]) * (h[j] - h[i]);
        if (i >= first && i < last) ah[i] += flow;
        if (j >= first && j < last) ah[j] -= flow;
      }
    }
  };
  over_two_halves(nodes, add_for_nodes);
  return ah;
}

// body(first, last) over the two halves of 0 … count − 1, side by side on two threads where the
// mesh is large enough (from some 50,000 triangles) to pay for waking the second.
template <class Body>
void DarcySolver::over_two_halves(int count, Body&& body) const {
  geometry::run_two_parts(mesh_.triangle_count() >= 50000, [&](int part) {
    const auto [first, last] = geometry::half_range(part, static_cast<std::size_t>(count));
    body(static_cast<int>(first), static_cast<int>(last));
  });
}

std::vector<double> DarcySolver::expand_heads(const Eigen::VectorXd& x) const {
  std::vector<double> h(fixed_head_);
  for (int u = 0; u < unknown_count(); ++u) h[free_nodes_[u]] = x[u];
  return h;
}

// r = f − A x over the unknowns, f_i = −∫ φ_i q_N ds, and the mass balance it implies:
// |Σ_i r_i| over the nodal flows through the boundary, (Σ_fixed |reaction| + Σ|q_N L|) / 2.
DarcySolver::Residual DarcySolver::compute_residual(const Eigen::VectorXd& x) const {
  const std::vector<long double> ah = compute_a_times_h(expand_heads(x));
  Residual out{Eigen::VectorXd(unknown_count()), 0.0, 0.0, 0.0};
  long double sum = 0.0L, boundary = 0.0L;
  for (int u = 0; u < unknown_count(); ++u) {
    const int v = free_nodes_[u];
    const long double r = -static_cast<long double>(neumann_outflow_[v]) - ah[v];
    out.r[u] = static_cast<double>(r);
    sum += r;
  }
  for (int v = 0; v < mesh_.node_count(); ++v)
    if (unknown_of_node_[v] < 0) boundary += std::abs(ah[v] + static_cast<long double>(neumann_outflow_[v]));
  for (double q : prescribed_flow_) boundary += std::abs(q);
  out.balance = boundary > 0.0L ? static_cast<double>(std::abs(sum) / (0.5L * boundary)) : 0.0;
  out.boundary = static_cast<double>(0.5L * boundary);
  out.net = net_boundary_flow(boundary_totals(ah));
  return out;
}

void DarcySolver::check_size(PermeabilityView permeability) const {
  if (permeability.size() != mesh_.triangles.size())
    throw std::runtime_error("flow: " + std::to_string(permeability.size()) + " permeabilities for " +
                             std::to_string(mesh_.triangles.size()) + " triangles");
  check_permeability(permeability);
}

FlowSolution DarcySolver::solve_and_keep(PermeabilityView permeability) {
  FlowSolution out = solve_with(permeability);
  factored_ = kept_ = std::make_shared<const PermeabilityField>(permeability);
  return out;
}

FlowSolution DarcySolver::solve(PermeabilityView permeability) {
  check_size(permeability);
  return solve_and_keep(permeability);
}

void DarcySolver::factorize_system(SolveTimings& timings, PermeabilityView permeability) {
  const auto clock = Clock::now();
  try {
    solver_->factorize(matrix_);
  } catch (const SingularSystem&) {
    // The solver's own words are linear algebra's: the user is told what the model met.
    throw FlowSolveFailed(describe_flow_failure(mesh_, permeability, fixed_head_, "its matrix could not be factored"));
  }
  timings.factorize = seconds_since(clock);
}

Eigen::VectorXd DarcySolver::solve_directly(int& refinement_steps) const {
  Eigen::VectorXd x = solver_->solve(rhs_);
  double last_residual = INFINITY;
  // Iterative refinement with the residual in extended precision, x += A⁻¹(f − A x): the
  // contrast of fracture-like strips (1e5–1e6) makes the plain solve lose as many digits,
  // and the mass balance needs them back. One back-substitution and one product a step,
  // until the balance is 1e4 times inside its 1e-10 bound or the residual stops shrinking.
  for (int step = 0; step < kMaxRefinementSteps; ++step) {
    const Residual residual = compute_residual(x);
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
  assemble_system(permeability);
  timings.assemble = seconds_since(clock);

  Eigen::VectorXd x(unknown_count());
  int refinement_steps = 0;
  if (unknown_count() > 0) {
    factorize_system(timings, permeability);
    clock = Clock::now();
    x = solve_directly(refinement_steps);
    if (!x.allFinite())
      throw FlowSolveFailed(describe_flow_failure(mesh_, permeability, fixed_head_, "its heads came out not finite"));
    timings.solve = seconds_since(clock);
  }
  clock = Clock::now();
  FlowSolution out = make_solution(x, permeability);
  timings.postprocess = seconds_since(clock);
  out.timings = timings;
  out.refinement_steps = refinement_steps;
  return out;
}

FlowSolution DarcySolver::solve_reusing_factor(PermeabilityView permeability, std::span<const double> start_heads) {
  check_size(permeability);
  if (!start_heads.empty() && start_heads.size() != mesh_.nodes.size())
    throw std::invalid_argument("flow: the starting heads must be one per node");
  if (unknown_count() == 0) return solve_and_keep(permeability);
  Preconditioning plan = plan_preconditioning(permeability, true);
  if (plan.bound > kHopelessIterations) return solve_and_keep(permeability);

  SolveTimings timings;
  auto clock = Clock::now();
  assemble_system(permeability);
  timings.assemble = seconds_since(clock);
  clock = Clock::now();
  // The elements that jumped, taken exactly by a low-rank correction of the kept factor; where
  // the solver has none, or the corrected matrix is singular to working precision, the kept
  // factor alone if it will do. Without a correction the kept factor only preconditions from
  // here, in single precision where the solver can: CG's iterations read half the memory, and
  // the factor holds half while the blocks move. A correction of such a factor only adds: a
  // stretch that closed by 10⁷ leaves 10⁻⁷ of its elements' conductance in the corrected
  // matrix, no more than the factor's rounding to float, which would then swamp it (made so in
  // bench_hydro's LatePassFlow/10/1/60, it left CG too slow for every other pass, which
  // factored afresh); such a correction is not made.
  std::unique_ptr<CorrectedFactor> corrected;
  if (plan.corrected.empty()) {
    solver_->keep_for_preconditioning();
  } else {
    const LowRankTerm term = element_changes(plan.corrected, permeability);
    const bool downdates = std::any_of(term.weight.begin(), term.weight.end(), [](double w) { return w < 0.0; });
    if (!downdates || !solver_->kept_for_preconditioning()) {
      try {
        corrected = solver_->correct(term);
      } catch (const SingularSystem&) {
      }
    }
    if (!corrected) {
      plan = plan_preconditioning(permeability, false);
      if (plan.bound > kHopelessIterations) {
        FlowSolution out = solve_and_keep(permeability);
        out.timings.assemble += timings.assemble;
        return out;
      }
    }
  }
  timings.factorize = seconds_since(clock);
  clock = Clock::now();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(unknown_count());
  if (!start_heads.empty())
    for (int u = 0; u < unknown_count(); ++u) x[u] = start_heads[free_nodes_[u]];
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
    if (!solve_by_conjugate_gradients(x, kMaxIterations - taken, taken, corrected.get())) break;
    timings.solve = seconds_since(clock);
    clock = Clock::now();
    out = make_solution(x, permeability);
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
  corrected.reset();
  out = solve_and_keep(permeability);
  out.timings.assemble += timings.assemble;
  out.cg_iterations = taken;
  return out;
}

namespace {

constexpr std::array<double, 8> kSpreads{1.001, 1.003, 1.01, 1.03, 1.1, 1.3, 2.0, 10.0};
constexpr int kNoBound = std::numeric_limits<int>::max();
// How many elements corrected exactly cost about one CG iteration: the half-solves along their
// paths up the elimination tree, and the iterations CG then adds where they closed (a downdate
// by 1e7 of an element's conductance leaves the correction accurate to about 1% in its
// directions). bench_hydro's LatePassFlow at 10^6 triangles: 100 closed elements cost 0.02 s
// to correct and one more iteration; an iteration (a whole solve and a product) 0.08 s.
constexpr double kCorrectedPerIteration = 80.0;
// What keeping the factor saves over a fresh one, in iterations: at 10^6 triangles a fresh
// factorisation and its exact solve take 0.43–0.48 s on two threads (0.60–0.67 s on one), a
// pass of four CG iterations on the kept factor 0.38–0.44 s (0.54–0.58 s): about one
// iteration. A correction that costs more is not made.
constexpr double kIterationsSavedByKeeping = 1.0;

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

// CG's iterations to cut the error by kHeadTolerance when every eigenvalue is in [1/c, c].
long chebyshev_iterations(double c) {
  return static_cast<long>(
      std::ceil(std::log(0.5 * DarcySolver::kHeadTolerance) / std::log((c - 1.0) / (c + 1.0))));
}

}  // namespace

// The kept factor is M = Σ_e K_e(k⁰_e), the new matrix A = Σ_e K_e(k_e), with
// K_e(k) = area_e Bᵀ k B the element matrix of a permeability tensor k (B the shape
// gradients). For any x, with g = B x, xᵀK_e(k)x / xᵀK_e(k⁰)x = gᵀ k g / gᵀ k⁰ g lies between
// the generalised eigenvalues of the pencil (k, k⁰), the roots λ of det(k − λ k⁰) = 0:
//   λ² det k⁰ − λ (k⁰xx kyy + k⁰yy kxx − 2 k⁰xy kxy) + det k = 0;
// for isotropic or axis-aligned tensors simply kxx/k⁰xx and kyy/k⁰yy. An element's spread is
// the larger of λ_max and 1/λ_min. Elements with spread ≤ c keep the eigenvalues of M⁻¹A in
// [1/c, c] (Rayleigh quotients of sums of semidefinite terms); each element outside moves at
// most two eigenvalues out (its K_e has rank two). CG then needs at most
// 2 · #outside + log(ε/2) / log((c − 1)/(c + 1)) iterations to cut the error by ε (Saad,
// Iterative Methods, §6.11.3, with the outlying eigenvalues removed first; Axelsson and
// Lindskog, Numer. Math. 48, 1986). The least over a ladder of c, with ε = kHeadTolerance.
// With the elements outside taken into M exactly (a low-rank correction), the first term goes.
std::vector<long> DarcySolver::count_outside(PermeabilityView permeability) const {
  std::vector<long> outside(kSpreads.size(), 0);
  const PermeabilityView kept = kept_->view();
  for (std::size_t e = 0; e < permeability.size(); ++e) {
    const double spread = spread_of(permeability[e], kept[e]);
    for (std::size_t i = 0; i < kSpreads.size() && !(spread <= kSpreads[i]); ++i) ++outside[i];
  }
  return outside;
}

int DarcySolver::bound_iterations(PermeabilityView permeability) const {
  return plan_preconditioning(permeability, false).bound;
}

// The cheapest of: the kept factor alone (bound_iterations), or corrected for the elements
// outside one spread of the ladder, each corrected element costing 1/kCorrectedPerIteration of
// an iteration. A correction is made only where the elements left let CG finish within its
// kMaxIterations, and where it costs less than keeping the factor saves: where a whole
// fracture network drifts by several per cent a pass, or hundreds of elements jump, a fresh
// factor is the cheaper.
DarcySolver::Preconditioning DarcySolver::plan_preconditioning(PermeabilityView permeability, bool correcting) const {
  if (!kept_ || kept_->size() != permeability.size()) return {{}, kNoBound};
  const std::vector<long> outside = count_outside(permeability);
  long bound = kNoBound;
  double cost = INFINITY;
  int corrected_outside = -1;  // the ladder step whose outside elements are corrected
  for (std::size_t i = 0; i < kSpreads.size(); ++i) {
    const long plain = 2 * outside[i] + chebyshev_iterations(kSpreads[i]);
    if (plain < cost) {
      cost = static_cast<double>(plain);
      bound = plain;
      corrected_outside = -1;
    }
    const double correction_cost = outside[i] / kCorrectedPerIteration;
    const double with_correction = static_cast<double>(chebyshev_iterations(kSpreads[i])) + correction_cost;
    if (correcting && outside[i] > 0 && outside[i] <= kMaxCorrectedElements &&
        chebyshev_iterations(kSpreads[i]) <= kMaxIterations && correction_cost < kIterationsSavedByKeeping &&
        with_correction < cost) {
      cost = with_correction;
      bound = chebyshev_iterations(kSpreads[i]);
      corrected_outside = static_cast<int>(i);
    }
  }
  Preconditioning plan{{}, static_cast<int>(std::min<long>(bound, kNoBound))};
  if (corrected_outside >= 0) {
    const PermeabilityView kept = kept_->view();
    for (std::size_t e = 0; e < permeability.size(); ++e)
      if (!(spread_of(permeability[e], kept[e]) <= kSpreads[corrected_outside]))
        plan.corrected.push_back(static_cast<int>(e));
  }
  return plan;
}

// K_e(k) − K_e(k⁰) = area_e Bᵀ (K − K⁰) B, K the conductivity; with the change of the tensor
// K − K⁰ = Σ λ_i v_i v_iᵀ (its eigenpairs), = Σ λ_i area_e (Bᵀ v_i)(Bᵀ v_i)ᵀ: a column Bᵀ v_i
// (∇φ_j · v_i at each free corner j) and a weight λ_i area_e for each nonzero λ_i.
LowRankTerm DarcySolver::element_changes(std::span<const int> elements, PermeabilityView permeability) const {
  LowRankTerm term;
  const PermeabilityView kept = kept_->view();
  const double factor = problem_.fluid.conductivity_per_permeability();
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
    const auto& tri = mesh_.triangles[e];
    const double area = std::abs(mesh::triangle_area(mesh_, e));
    const auto g = compute_shape_gradients(mesh_.nodes[tri[0]], mesh_.nodes[tri[1]], mesh_.nodes[tri[2]]);
    for (const auto& [lambda, v] : modes) {
      if (lambda == 0.0) continue;
      const std::size_t before = term.row.size();
      for (int i = 0; i < 3; ++i) {
        const int u = unknown_of_node_[tri[i]];
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
    check_size(kept->view());
    assemble_system(kept->view());
    SolveTimings timings;
    if (unknown_count() > 0) factorize_system(timings, kept->view());
    factored_ = kept;
  }
  kept_ = std::move(kept);
  if (kept_ && single_precision && unknown_count() > 0) solver_->keep_for_preconditioning();
}

// Preconditioned CG (numerics/conjugate_gradients.hpp), M the kept factor, stopped here when
// |z|∞ ≤ kHeadTolerance · range(h), z = M⁻¹ r being the error A⁻¹ r as far as M is A; and
// |Σ r| ≤ kBalanceTolerance / 10 of the boundary flow at the start, Σ r being what the boundary
// flows fail to balance by (compute_boundary_flows). Gives up past `budget` iterations, as soon
// as the rate so far says the budget will not do, or when CG breaks down.
bool DarcySolver::solve_by_conjugate_gradients(Eigen::VectorXd& x, int budget, int& iterations,
                                               const CorrectedFactor* corrected) const {
  const auto multiply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) {
    y = matrix_.selfadjointView<Eigen::Upper>() * v;
  };
  const auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd& z) {
    z = corrected ? corrected->solve(v) : solver_->precondition(v);
  };
  // The heads' range, fixed ones included: the scale of the head error that counts.
  const auto head_tolerance = [&] {
    const double lo = std::min(x.minCoeff(), fixed_head_range_[0]), hi = std::max(x.maxCoeff(), fixed_head_range_[1]);
    const double scale = hi > lo ? hi - lo : std::max({std::abs(lo), std::abs(hi), 1e-300});
    return kHeadTolerance * scale;
  };
  // The starting residual in extended precision, as the refinement takes it.
  const Residual start = compute_residual(x);
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

FlowSolution DarcySolver::make_solution(const Eigen::VectorXd& x, PermeabilityView permeability) const {
  FlowSolution out;
  const int node_count = mesh_.node_count();
  out.reference_head = reference_head_;
  out.head.resize(node_count);
  for (int v = 0; v < node_count; ++v)
    out.head[v] = unknown_of_node_[v] < 0 ? fixed_head_[v] : x[unknown_of_node_[v]];
  const double rho_g = problem_.fluid.unit_weight();
  out.pressure.resize(node_count);
  for (int v = 0; v < node_count; ++v)
    out.pressure[v] = problem_.pressure == PressureConvention::overpressure
                          ? rho_g * (out.head[v] - reference_head_)   // p = ρg (h − h_ref)
                          : rho_g * (out.head[v] - mesh_.nodes[v].y); // p = ρg (h − z)
  out.flux.resize(mesh_.triangles.size());
  const double factor = problem_.fluid.conductivity_per_permeability();
  over_two_halves(mesh_.triangle_count(), [&](int first, int last) {
    for (int t = first; t < last; ++t) {
      const auto& tri = mesh_.triangles[t];
      const auto g = compute_shape_gradients(mesh_.nodes[tri[0]], mesh_.nodes[tri[1]], mesh_.nodes[tri[2]]);
      // ∇h = Σ h_i ∇φ_i;  q = −K ∇h
      const geometry::Point grad = out.head[tri[0]] * g[0] + out.head[tri[1]] * g[1] + out.head[tri[2]] * g[2];
      const Conductivity k = conductivity(permeability[t], factor);
      out.flux[t] = {-(k.xx * grad.x + k.xy * grad.y), -(k.xy * grad.x + k.yy * grad.y)};
    }
  });
  compute_boundary_flows(out);
  return out;
}

// Boundary flows from the residual of the assembled (unreduced) system. With the weak form
//   Σ_j A_ij h_j = −∫_Γ φ_i q·n ds,
// the total outflow at node i is O_i = −(A h)_i; at a fixed node, the part not prescribed
// by a flux edge, O_i − ∫ φ_i q_N ds, is its reaction, owed to its fixed boundaries (shared
// by edge length where two meet). Since Σ_i (A h)_i = 0 exactly (compute_a_times_h), all
// boundary flows add up to minus the sum of the free rows' residual: the balance error is
// the solver's, whatever the mesh.
std::vector<double> DarcySolver::boundary_totals(const std::vector<long double>& a_times_h) const {
  std::vector<double> flow = prescribed_flow_;
  for (const FixedShare& s : fixed_shares_)
    flow[s.boundary] += static_cast<double>(
        s.weight * (-a_times_h[s.node] - static_cast<long double>(neumann_outflow_[s.node])));
  return flow;
}

double DarcySolver::net_boundary_flow(const std::vector<double>& flow) {
  double inflow = 0.0, outflow = 0.0;
  for (double q : flow) (q < 0 ? inflow : outflow) += std::abs(q);
  return std::max(inflow, outflow);
}

void DarcySolver::compute_boundary_flows(FlowSolution& out) const {
  const std::vector<double> flow = boundary_totals(compute_a_times_h(out.head));
  out.boundary_flows.clear();
  double sum = 0.0;
  for (std::size_t b = 0; b < flow.size(); ++b) {
    out.boundary_flows.push_back({mesh_.boundary_names[b], flow[b]});
    sum += flow[b];
  }
  const double scale = net_boundary_flow(flow);
  out.balance_error = scale > 0.0 ? std::abs(sum) / scale : 0.0;
}

}  // namespace hydrodda::hydro
