#include "hydro/darcy_assembly.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hydrodda::hydro {
namespace {

// The three node pairs of a triangle whose couplings K_e(i, j), i ≠ j, are kept.
constexpr std::array<std::array<int, 2>, 3> kEdgePairs{{{0, 1}, {0, 2}, {1, 2}}};
// The six local pairs (i, j) whose values enter the upper triangle, at (row, column) =
// (min, max) of their unknowns.
constexpr std::array<std::array<int, 2>, 6> kLocalPairs{{{0, 0}, {1, 1}, {2, 2}, {1, 0}, {2, 0}, {2, 1}}};

}  // namespace

std::array<std::array<double, 3>, 3> compute_element_mass_matrix(double area, MassMatrix kind) {
  std::array<std::array<double, 3>, 3> m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m[i][j] = kind == MassMatrix::lumped ? (i == j ? area / 3.0 : 0.0)  // ∫ φ_i, on the diagonal
                                           : area / 12.0 * (i == j ? 2.0 : 1.0);  // ∫ φ_i φ_j
  return m;
}

Eigen::SparseMatrix<double> assemble_mass_matrix(const mesh::TriangleMesh& mesh, MassMatrix kind) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * mesh.triangles.size());
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const auto& tri = mesh.triangles[t];
    const auto m = compute_element_mass_matrix(std::abs(mesh::triangle_area(mesh, t)), kind);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (m[i][j] != 0.0) entries.emplace_back(tri[i], tri[j], m[i][j]);
  }
  Eigen::SparseMatrix<double> mass(mesh.node_count(), mesh.node_count());
  mass.setFromTriplets(entries.begin(), entries.end());
  return mass;
}

DarcyAssembler::DarcyAssembler(const mesh::TriangleMesh& mesh, DarcyProblem problem)
    : mesh_(mesh), problem_(std::move(problem)) {
  const auto start = std::chrono::steady_clock::now();
  if (!(problem_.fluid.density > 0.0) || !(problem_.fluid.viscosity > 0.0) ||
      !(problem_.fluid.gravity > 0.0))
    throw std::runtime_error("fluid density, viscosity and gravity must be positive");
  mesh::validate(mesh_);
  setup_boundary_conditions();
  setup_pattern();
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void DarcyAssembler::set_boundary_values(std::span<const BoundaryCondition> boundaries) {
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

void DarcyAssembler::setup_boundary_conditions() {
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
  fixed_shares_ = share_by_edge_length(std::move(shares));
  if (fixed_shares_.empty())
    throw std::runtime_error(
        "flow: nothing fixes the head (give a head or pressure condition on at least one "
        "named boundary); the problem has no unique solution");

  check_every_part_is_fixed();
  number_unknowns();
}

// Each fixed node's shares (one per fixed edge end) summed per boundary and scaled to sum to one.
std::vector<DarcyAssembler::FixedShare> DarcyAssembler::share_by_edge_length(std::vector<FixedShare> shares) {
  std::vector<FixedShare> fixed_shares;
  std::sort(shares.begin(), shares.end(), [](const FixedShare& a, const FixedShare& b) {
    return a.node != b.node ? a.node < b.node : a.boundary < b.boundary;
  });
  for (std::size_t i = 0; i < shares.size();) {
    std::size_t j = i;
    double total = 0.0;
    while (j < shares.size() && shares[j].node == shares[i].node) total += shares[j++].weight;
    for (std::size_t k = i; k < j; ++k) {
      if (!fixed_shares.empty() && fixed_shares.back().node == shares[k].node &&
          fixed_shares.back().boundary == shares[k].boundary)
        fixed_shares.back().weight += shares[k].weight / total;
      else
        fixed_shares.push_back({shares[k].node, shares[k].boundary, shares[k].weight / total});
    }
    i = j;
  }
  return fixed_shares;
}

// The free nodes numbered in node order, and the range of the fixed heads.
void DarcyAssembler::number_unknowns() {
  fixed_head_range_ = {INFINITY, -INFINITY};
  for (double h : fixed_head_)
    if (!std::isnan(h)) fixed_head_range_ = {std::min(fixed_head_range_[0], h), std::max(fixed_head_range_[1], h)};
  unknown_of_node_.assign(fixed_head_.size(), -1);
  free_nodes_.clear();
  for (int v = 0; v < static_cast<int>(fixed_head_.size()); ++v)
    if (std::isnan(fixed_head_[v])) {
      unknown_of_node_[v] = static_cast<int>(free_nodes_.size());
      free_nodes_.push_back(v);
    }
}

// A part of the mesh that touches no fixed node has no unique head (the matrix is singular
// there, though a factorisation may only see a tiny pivot): find the parts with a
// union–find over the triangles' nodes and refuse any part without a fixed node.
void DarcyAssembler::check_every_part_is_fixed() const {
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

void DarcyAssembler::setup_pattern() {
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
}

void DarcyAssembler::assemble(PermeabilityView permeability) {
  storage_.reset();
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

// A_uv += c_e M_e(i, j) for the free corners u, v of each triangle, into the pattern's entries;
// f_u += c_e Σ_j M_e(i, j) h_old_j, less c_e M_e(i, j) h_j for each fixed corner j.
void DarcyAssembler::add_storage(std::span<const double> storage_over_step, MassMatrix kind,
                                 std::span<const double> previous_heads) {
  if (previous_heads.size() != mesh_.nodes.size())
    throw std::invalid_argument("flow: the previous heads must be one per node");
  if (storage_over_step.size() != mesh_.triangles.size())
    throw std::invalid_argument("flow: the storage coefficients must be one per triangle");
  for (double c : storage_over_step)
    if (!std::isfinite(c) || c < 0.0)
      throw std::invalid_argument("flow: the storage coefficient over the step must be finite and not negative");
  if (storage_) throw std::logic_error("flow: storage added twice to one assembly");
  double* values = matrix_.valuePtr();
  const int* outer = matrix_.outerIndexPtr();
  for (int t = 0; t < mesh_.triangle_count(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const double c = storage_over_step[t];
    const auto m = compute_element_mass_matrix(std::abs(mesh::triangle_area(mesh_, t)), kind);
    for (int i = 0; i < 3; ++i) {
      const int u = unknown_of_node_[tri[i]];
      if (u < 0) continue;
      values[outer[u + 1] - 1] += c * m[i][i];
      for (int j = 0; j < 3; ++j) {
        rhs_[u] += c * m[i][j] * previous_heads[tri[j]];
        if (unknown_of_node_[tri[j]] < 0) rhs_[u] -= c * m[i][j] * fixed_head_[tri[j]];
      }
    }
    const int* entry = &entry_[3 * static_cast<std::size_t>(t)];
    for (int p = 3; p < 6; ++p)
      if (entry[p - 3] >= 0) values[entry[p - 3]] += c * m[kLocalPairs[p][0]][kLocalPairs[p][1]];
  }
  storage_ = Storage{{storage_over_step.begin(), storage_over_step.end()}, kind,
                     {previous_heads.begin(), previous_heads.end()}};
}

void DarcyAssembler::add_storage(double storage_over_step, MassMatrix kind, std::span<const double> previous_heads) {
  add_storage(std::vector<double>(mesh_.triangles.size(), storage_over_step), kind, previous_heads);
}

// (c M (h − h_old))_i = Σ_e c_e Σ_j M_e(i, j) (h_j − h_old,j) for the nodes of [first, last),
// each from its triangles in triangle order: the same sums whatever the shares.
void DarcyAssembler::add_storage_rates(const std::vector<double>& h, int first, int last,
                                       std::vector<long double>& ah) const {
  for (int t = 0; t < mesh_.triangle_count(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const double c = storage_->coefficient[t];
    if (c == 0.0) continue;
    const auto m = compute_element_mass_matrix(std::abs(mesh::triangle_area(mesh_, t)), storage_->kind);
    for (int i = 0; i < 3; ++i) {
      if (tri[i] < first || tri[i] >= last) continue;
      long double rate = 0.0L;
      for (int j = 0; j < 3; ++j)
        if (m[i][j] != 0.0) rate += static_cast<long double>(m[i][j]) * (h[tri[j]] - storage_->previous_heads[tri[j]]);
      ah[tri[i]] += static_cast<long double>(c) * rate;
    }
  }
}

double DarcyAssembler::storage_rate(const std::vector<double>& h) const {
  if (!storage_) return 0.0;
  std::vector<long double> rates(h.size(), 0.0L);
  add_storage_rates(h, 0, static_cast<int>(h.size()), rates);
  long double total = 0.0L;
  for (long double r : rates) total += r;
  return static_cast<double>(total);
}

// (A h)_i for every node, from the element matrices kept by assemble(), in the
// pairwise form (A h)_i = Σ_e Σ_{j≠i} K_e(i, j) (h_j − h_i) (rows of K_e sum to zero). Each
// pair enters node i and node j with opposite signs, bit for bit, so Σ_i (A h)_i = 0 to the
// long-double accumulation: the boundary flows then balance to round-off whatever the
// contrast, and the residual that drives the iterative refinement is the same one.
// On several threads each takes the nodes of one share of the numbering and adds, for them
// only, the same terms in the same order as one thread does: the sums are the same, bit for
// bit, whatever the shares.
std::vector<long double> DarcyAssembler::compute_a_times_h(const std::vector<double>& h) const {
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
    if (storage_) add_storage_rates(h, first, last, ah);
  };
  over_thread_shares(nodes, add_for_nodes);
  return ah;
}

std::vector<double> DarcyAssembler::expand_heads(const Eigen::VectorXd& x) const {
  std::vector<double> h(fixed_head_);
  for (int u = 0; u < unknown_count(); ++u) h[free_nodes_[u]] = x[u];
  return h;
}

// r = f − A x over the unknowns, f_i = −∫ φ_i q_N ds, and the mass balance it implies:
// |Σ_i r_i| over the nodal flows through the boundary, (Σ_fixed |reaction| + Σ|q_N L|) / 2.
DarcyAssembler::Residual DarcyAssembler::compute_residual(const Eigen::VectorXd& x) const {
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

void DarcyAssembler::check_size(PermeabilityView permeability) const {
  if (permeability.size() != mesh_.triangles.size())
    throw std::runtime_error("flow: " + std::to_string(permeability.size()) + " permeabilities for " +
                             std::to_string(mesh_.triangles.size()) + " triangles");
  check_permeability(permeability);
}

// Boundary flows from the residual of the assembled (unreduced) system. With the weak form
//   Σ_j A_ij h_j = −∫_Γ φ_i q·n ds,
// the total outflow at node i is O_i = −(A h)_i; at a fixed node, the part not prescribed
// by a flux edge, O_i − ∫ φ_i q_N ds, is its reaction, owed to its fixed boundaries (shared
// by edge length where two meet). Since Σ_i (A h)_i = 0 exactly (compute_a_times_h), all
// boundary flows add up to minus the sum of the free rows' residual: the balance error is
// the solver's, whatever the mesh.
std::vector<double> DarcyAssembler::boundary_totals(const std::vector<long double>& a_times_h) const {
  std::vector<double> flow = prescribed_flow_;
  for (const FixedShare& s : fixed_shares_)
    flow[s.boundary] += static_cast<double>(
        s.weight * (-a_times_h[s.node] - static_cast<long double>(neumann_outflow_[s.node])));
  return flow;
}

double DarcyAssembler::net_boundary_flow(const std::vector<double>& flow) {
  double inflow = 0.0, outflow = 0.0;
  for (double q : flow) (q < 0 ? inflow : outflow) += std::abs(q);
  return std::max(inflow, outflow);
}

}  // namespace hydrodda::hydro
