#pragma once
// The linear system of Darcy flow in hydraulic head with P1 finite elements on a fixed mesh:
//   −∇·(K ∇h) = 0 in Ω,  K = k ρ_w g / μ,
//   h = h_D on fixed-head (or fixed-pressure) boundaries, q·n = q_N on flux boundaries,
//   q·n = 0 elsewhere;
// reduced to the unknown (free) heads, A x = f. Built once per mesh and set of boundary
// conditions (numbering, sparsity pattern); assemble() refills the values in place. What the
// linear solver does with it is darcy_solver.hpp's; what is made of its answer,
// darcy_postprocessing.hpp's.
//
// Storage: add_storage() adds Σ_e c_e M_e, M_e the P1 mass matrix of element e (lumped or
// consistent) and c_e = S_s,e/Δt (S_s the specific storage in head, 1/m), and Σ_e c_e M_e h_old
// to the right-hand side, for a backward-Euler step of
//   S_s ∂h/∂t − ∇·(K ∇h) = 0
// (docs/flow.md, "Transient flow"). Steady solves never add it; assemble() drops it.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "numerics/parallel.hpp"
#include "hydro/boundary_condition.hpp"
#include "hydro/fluid.hpp"
#include "hydro/linear_solver.hpp"
#include "hydro/p1_element.hpp"
#include "hydro/permeability_field.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

struct DarcyProblem {
  Fluid fluid;
  std::vector<BoundaryCondition> boundaries;
  PressureConvention pressure = PressureConvention::overpressure;
};

// K = k ρ_w g / μ, `factor` = ρ_w g / μ.
inline Conductivity conductivity(const PermeabilityTensor& k, double factor) {
  return {k.xx * factor, k.xy * factor, k.yy * factor};
}

// The P1 mass matrix M_e(i, j) = ∫_e φ_i φ_j: consistent, A/12 (1 + δ_ij); or lumped, its
// rows summed onto the diagonal, A/3 δ_ij. Both integrate a P1 function exactly: 1ᵀ M u = ∫ u.
enum class MassMatrix { lumped, consistent };
std::array<std::array<double, 3>, 3> compute_element_mass_matrix(double area, MassMatrix kind);
// M over every node of the mesh.
Eigen::SparseMatrix<double> assemble_mass_matrix(const mesh::TriangleMesh& mesh, MassMatrix kind);

class DarcyAssembler {
 public:
  // Keeps a reference to `mesh`, which must outlive the assembler. Throws std::runtime_error
  // when a condition names an unknown or empty boundary, or when nothing fixes the head
  // (SingularSystem when some connected part of the mesh has no fixed head).
  DarcyAssembler(const mesh::TriangleMesh& mesh, DarcyProblem problem);

  // New values for the same conditions (DarcySolver::set_boundary_values).
  void set_boundary_values(std::span<const BoundaryCondition> boundaries);
  const DarcyProblem& problem() const { return problem_; }
  const mesh::TriangleMesh& mesh() const { return mesh_; }

  // One permeability per triangle, each finite and positive definite (std::runtime_error).
  void check_size(PermeabilityView permeability) const;
  // A and f from an intrinsic permeability (m²) per triangle; A's pattern stays.
  void assemble(PermeabilityView permeability);
  // A += Σ_e c_e M_e and f += Σ_e c_e M_e h_old over the unknowns (the fixed heads' columns
  // carried to f), c_e = S_s,e/Δt (1/s, one per triangle, or one for all): the storage term of
  // a backward-Euler step from `previous_heads` (one per node). From here until the next
  // assemble(), the residual, A h and so the boundary flows count the water each node stores,
  // c M (h − h_old): a fixed node's reaction includes what its own storage takes.
  void add_storage(std::span<const double> storage_over_step, MassMatrix kind, std::span<const double> previous_heads);
  void add_storage(double storage_over_step, MassMatrix kind, std::span<const double> previous_heads);
  bool has_storage() const { return storage_.has_value(); }
  // The rate at which water goes into storage, Σ_i (c M (h − h_old))_i (m²/s per metre of
  // thickness); 0 without storage.
  double storage_rate(const std::vector<double>& h) const;
  // The upper triangle of A over the unknowns, and f.
  const SparseMatrix& matrix() const { return matrix_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

  int unknown_count() const { return static_cast<int>(free_nodes_.size()); }
  const std::vector<int>& free_nodes() const { return free_nodes_; }      // per unknown: its node
  const std::vector<int>& unknown_of_node() const { return unknown_of_node_; }  // −1: fixed
  const std::vector<double>& fixed_head() const { return fixed_head_; }  // per node: NaN where free
  std::array<double, 2> fixed_head_range() const { return fixed_head_range_; }
  double reference_head() const { return reference_head_; }
  double setup_seconds() const { return setup_seconds_; }

  // Every node's head: the fixed ones and x over the unknowns.
  std::vector<double> expand_heads(const Eigen::VectorXd& x) const;
  // (A h)_i for every node, from the last assemble(), in extended precision (see the .cpp); with
  // storage, plus (c M (h − h_old))_i.
  std::vector<long double> compute_a_times_h(const std::vector<double>& h) const;
  struct Residual {
    Eigen::VectorXd r;  // f − A x over the unknowns
    double balance;     // the relative mass-balance error it implies
    double boundary;    // the flow it is relative to: Σ |nodal flow through the boundary| / 2
    double net;         // the larger of the boundaries' total inflow and total outflow
  };
  Residual compute_residual(const Eigen::VectorXd& x) const;
  // The flow out through each mesh boundary, from A h (compute_a_times_h).
  std::vector<double> boundary_totals(const std::vector<long double>& a_times_h) const;
  // The larger of the boundaries' total inflow and total outflow.
  static double net_boundary_flow(const std::vector<double>& flow);

  // body(first, last) over one share of 0 … count − 1 per thread, side by side where the mesh is
  // large enough (from some 50,000 triangles) to pay for waking the threads. For bodies whose
  // every index comes out the same whatever share holds it (numerics::for_each_share).
  template <class Body>
  void over_thread_shares(int count, Body&& body) const {
    const int shares = mesh_.triangle_count() >= 50000 ? numerics::thread_count() : 1;
    numerics::for_each_share(shares, static_cast<std::size_t>(count), [&](int, std::size_t first, std::size_t last) {
      body(static_cast<int>(first), static_cast<int>(last));
    });
  }

 private:
  void setup_boundary_conditions();
  void check_every_part_is_fixed() const;
  void number_unknowns();
  void setup_pattern();
  // Adds (c M (h − h_old))_i to `ah` for the nodes first … last − 1.
  void add_storage_rates(const std::vector<double>& h, int first, int last, std::vector<long double>& ah) const;

  const mesh::TriangleMesh& mesh_;
  DarcyProblem problem_;
  double reference_head_ = 0.0;
  double setup_seconds_ = 0.0;

  std::vector<double> fixed_head_;        // per node: NaN where the head is free
  std::array<double, 2> fixed_head_range_{};  // the smallest and largest fixed head
  std::vector<int> unknown_of_node_;      // per node: index of its unknown, −1 if fixed
  std::vector<int> free_nodes_;           // per unknown: its node
  std::vector<double> neumann_outflow_;   // per node: ∫ φ_i q_N over flux edges (m²/s)
  std::vector<int> entry_;                // per triangle, its 3 off-diagonal value positions (−1: none)
  std::vector<int> fixed_elements_;       // triangles with at least one fixed node
  struct FixedShare {                     // part of a fixed node's reaction owed to a boundary
    int node;
    int boundary;
    double weight;                        // share of the node's fixed-boundary edge length
  };
  static std::vector<FixedShare> share_by_edge_length(std::vector<FixedShare> shares);
  std::vector<FixedShare> fixed_shares_;  // sorted by node
  std::vector<double> prescribed_flow_;   // per mesh boundary: ∫ q_N ds over its flux edges
  std::vector<double> element_coupling_;  // per triangle, K_e(0,1), K_e(0,2), K_e(1,2)
  struct Storage {                        // the storage term since the last assemble()
    std::vector<double> coefficient;      // per triangle, c_e = S_s,e/Δt (1/s)
    MassMatrix kind = MassMatrix::lumped;
    std::vector<double> previous_heads;   // per node
  };
  std::optional<Storage> storage_;
  SparseMatrix matrix_;                   // upper triangle over the unknowns
  Eigen::VectorXd rhs_;
};

}  // namespace hydrodda::hydro
