#pragma once
// Steady Darcy flow in hydraulic head with P1 finite elements on a fixed triangle mesh:
//   −∇·(K ∇h) = 0 in Ω,  K = k ρ_w g / μ,
//   h = h_D on fixed-head (or fixed-pressure) boundaries, q·n = q_N on flux boundaries,
//   q·n = 0 elsewhere.
// Built once per mesh and set of boundary conditions (numbering, sparsity pattern, symbolic
// factorisation); each solve() refills the matrix values in place and refactors numerically.

#include <memory>
#include <span>
#include <vector>

#include "hydro/boundary_condition.hpp"
#include "hydro/flow_solution.hpp"
#include "hydro/fluid.hpp"
#include "hydro/linear_solver.hpp"
#include "hydro/p1_element.hpp"
#include "mesh/triangle_mesh.hpp"

namespace hydrodda::hydro {

struct DarcyProblem {
  Fluid fluid;
  std::vector<BoundaryCondition> boundaries;
  PressureConvention pressure = PressureConvention::overpressure;
};

class DarcySolver {
 public:
  // Keeps a reference to `mesh`, which must outlive the solver. Throws std::runtime_error
  // when a condition names an unknown or empty boundary, or when nothing fixes the head
  // (SingularSystem when some connected part of the mesh has no fixed head).
  DarcySolver(const mesh::TriangleMesh& mesh, DarcyProblem problem,
              std::unique_ptr<LinearSolver> solver = make_cholmod_solver());

  // Solves with an isotropic intrinsic permeability k (m²) per triangle.
  FlowSolution solve(std::span<const double> permeability);
  // Solves with a permeability tensor (m²) per triangle.
  FlowSolution solve(std::span<const PermeabilityTensor> permeability);

  // New values for the same conditions (the same boundaries, kinds and order), e.g. a head
  // raised between coupling passes: the fixed nodes stay, so the pattern and its analysis are
  // kept. Throws std::invalid_argument when the conditions differ in anything but their values.
  void set_boundary_values(std::span<const BoundaryCondition> boundaries);
  const std::vector<BoundaryCondition>& boundary_conditions() const { return problem_.boundaries; }

  int unknown_count() const { return static_cast<int>(free_nodes_.size()); }
  long long stored_nonzeros() const { return matrix_.nonZeros(); }
  double reference_head() const { return reference_head_; }
  // Seconds spent in the constructor: pattern and symbolic analysis.
  double setup_seconds() const { return setup_seconds_; }
  const std::string& solver_name() const { return solver_name_; }

 private:
  void setup_boundary_conditions();
  void check_every_part_is_fixed() const;
  void setup_pattern();
  void assemble_system(std::span<const Conductivity> conductivity);
  struct Residual {
    Eigen::VectorXd r;  // f − A x over the unknowns
    double balance;     // the relative mass-balance error it implies
  };
  Residual compute_residual(const Eigen::VectorXd& x) const;
  std::vector<long double> compute_a_times_h(const std::vector<double>& h) const;
  std::vector<double> expand_heads(const Eigen::VectorXd& x) const;
  FlowSolution solve_with(std::span<const Conductivity> conductivity);
  void compute_boundary_flows(FlowSolution& out) const;

  const mesh::TriangleMesh& mesh_;
  DarcyProblem problem_;
  std::unique_ptr<LinearSolver> solver_;
  std::string solver_name_;
  double reference_head_ = 0.0;
  double setup_seconds_ = 0.0;

  std::vector<double> fixed_head_;        // per node: NaN where the head is free
  std::vector<int> unknown_of_node_;      // per node: index of its unknown, −1 if fixed
  std::vector<int> free_nodes_;           // per unknown: its node
  std::vector<double> neumann_outflow_;   // per node: ∫ φ_i q_N over flux edges (m²/s)
  std::vector<int> entry_;                // per triangle, 6 value positions (−1: none)
  std::vector<int> fixed_elements_;       // triangles with at least one fixed node
  struct FixedShare {                     // part of a fixed node's reaction owed to a boundary
    int node;
    int boundary;
    double weight;                        // share of the node's fixed-boundary edge length
  };
  std::vector<FixedShare> fixed_shares_;  // sorted by node
  std::vector<double> prescribed_flow_;   // per mesh boundary: ∫ q_N ds over its flux edges
  std::vector<double> element_coupling_;  // per triangle, K_e(0,1), K_e(0,2), K_e(1,2)
  SparseMatrix matrix_;                   // lower triangle over the unknowns
  Eigen::VectorXd rhs_;
};

}  // namespace hydrodda::hydro
