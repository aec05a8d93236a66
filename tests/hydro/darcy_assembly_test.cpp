#include "hydro/darcy_assembly.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "flow_test_meshes.hpp"

namespace hydrodda::hydro {
namespace {

// [0, 2] × [0, 1], unstructured: area 2, centroid (1, 1/2).
const mesh::TriangleMesh& rectangle() {
  static const mesh::TriangleMesh m = testing::make_rectangle_mesh(2.0, 1.0, 0.2);
  return m;
}

DarcyProblem left_to_right() {
  DarcyProblem p;
  p.boundaries = {{"left", BoundaryKind::head, 3.0}, {"right", BoundaryKind::head, 1.0}};
  return p;
}

// Σ over the entries of M times the values at their ends: uᵀ M v.
double product(const Eigen::SparseMatrix<double>& m, const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  return u.dot(m * v);
}

TEST(MassMatrix, ElementMatricesHoldTheTrianglesAreaAndTheirKnownEntries) {
  const double area = 0.375;
  const auto lumped = compute_element_mass_matrix(area, MassMatrix::lumped);
  const auto consistent = compute_element_mass_matrix(area, MassMatrix::consistent);
  double lumped_sum = 0.0, consistent_sum = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      lumped_sum += lumped[i][j];
      consistent_sum += consistent[i][j];
      EXPECT_DOUBLE_EQ(lumped[i][j], i == j ? area / 3 : 0.0);
      EXPECT_DOUBLE_EQ(consistent[i][j], i == j ? area / 6 : area / 12);
    }
  EXPECT_DOUBLE_EQ(lumped_sum, area);
  EXPECT_DOUBLE_EQ(consistent_sum, area);
}

TEST(MassMatrix, AssembledItSumsToTheDomainsAreaAndIntegratesLinearFunctionsExactly) {
  const mesh::TriangleMesh& m = rectangle();
  const int n = m.node_count();
  Eigen::VectorXd one = Eigen::VectorXd::Ones(n), x(n), u(n);
  for (int v = 0; v < n; ++v) {
    x[v] = m.nodes[v].x;
    u[v] = 0.5 - 2.0 * m.nodes[v].x + 3.0 * m.nodes[v].y;
  }
  for (const MassMatrix kind : {MassMatrix::lumped, MassMatrix::consistent}) {
    const Eigen::SparseMatrix<double> mass = assemble_mass_matrix(m, kind);
    EXPECT_NEAR(product(mass, one, one), 2.0, 1e-13);
    // 1ᵀ M u = ∫ u for P1 u: area × u(centroid) = 2 (0.5 − 2 + 1.5) = 0.
    EXPECT_NEAR(product(mass, one, u), 0.0, 1e-13);
    EXPECT_NEAR(product(mass, one, x), 2.0, 1e-13);  // ∫ x = 2 × 1
  }
  // Consistent, uᵀ M u = ∫ u² for P1 u: ∫ x² over [0, 2] × [0, 1] = 8/3. Lumped it is not.
  EXPECT_NEAR(product(assemble_mass_matrix(m, MassMatrix::consistent), x, x), 8.0 / 3.0, 1e-13);
  EXPECT_GT(std::abs(product(assemble_mass_matrix(m, MassMatrix::lumped), x, x) - 8.0 / 3.0), 1e-4);
}

// A + c M and f + c M h_old − c M_free,fixed h_fixed over the unknowns, against the mass matrix
// assembled on its own.
TEST(DarcyAssembler, StorageAddsItsMassMatrixOverTheUnknowns) {
  const mesh::TriangleMesh& m = rectangle();
  DarcyAssembler system(m, left_to_right());
  const std::vector<double> k(m.triangles.size(), 1e-12);
  system.assemble(k);
  const Eigen::SparseMatrix<double> conductance = system.matrix();
  const Eigen::VectorXd rhs = system.rhs();
  std::vector<double> previous(m.nodes.size());
  for (int v = 0; v < m.node_count(); ++v) previous[v] = 2.0 + std::sin(3.0 * m.nodes[v].x + m.nodes[v].y);
  const double c = 0.25;
  for (const MassMatrix kind : {MassMatrix::lumped, MassMatrix::consistent}) {
    system.assemble(k);
    system.add_storage(c, kind, previous);
    const Eigen::MatrixXd added = Eigen::MatrixXd(system.matrix()) - Eigen::MatrixXd(conductance);
    const Eigen::MatrixXd mass = assemble_mass_matrix(m, kind);
    const std::vector<int>& free = system.free_nodes();
    Eigen::VectorXd expected_rhs = rhs;
    for (std::size_t a = 0; a < free.size(); ++a) {
      for (std::size_t b = a; b < free.size(); ++b) {
        EXPECT_NEAR(added(a, b), c * mass(free[a], free[b]), 1e-15) << a << ", " << b;
      }
      for (int v = 0; v < m.node_count(); ++v) {
        const bool fixed = system.unknown_of_node()[v] < 0;
        expected_rhs[a] += c * mass(free[a], v) * (previous[v] - (fixed ? system.fixed_head()[v] : 0.0));
      }
    }
    EXPECT_LT((system.rhs() - expected_rhs).lpNorm<Eigen::Infinity>(), 1e-13);
  }
  EXPECT_THROW(system.add_storage(c, MassMatrix::lumped, std::vector<double>(3, 0.0)), std::invalid_argument);
  EXPECT_THROW(system.add_storage(-1.0, MassMatrix::lumped, previous), std::invalid_argument);
}

// A backward-Euler step from the steady heads stays there: (A + c M) h = f + c M h_ss has
// h = h_ss, whatever c.
TEST(DarcyAssembler, AStepWithStorageFromTheSteadyStateStaysThere) {
  const mesh::TriangleMesh& m = rectangle();
  DarcyAssembler system(m, left_to_right());
  std::vector<double> k(m.triangles.size());
  for (int t = 0; t < m.triangle_count(); ++t) k[t] = mesh::triangle_centroid(m, t).y < 0.5 ? 1e-12 : 4e-12;
  system.assemble(k);
  const auto solve = [&] {
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper> ldlt(system.matrix());
    return system.expand_heads(ldlt.solve(system.rhs()));
  };
  const std::vector<double> steady = solve();
  for (const double c : {1e-6, 1.0, 1e3}) {
    system.assemble(k);
    system.add_storage(c, MassMatrix::consistent, steady);
    const std::vector<double> stepped = solve();
    for (int v = 0; v < m.node_count(); ++v) ASSERT_NEAR(stepped[v], steady[v], 1e-11) << c;
  }
  // From another state it moves: the storage term is really there.
  std::vector<double> flat(m.nodes.size(), 2.0);
  system.assemble(k);
  system.add_storage(1e3, MassMatrix::consistent, flat);
  const std::vector<double> stepped = solve();
  double largest_change = 0.0;
  for (int v = 0; v < m.node_count(); ++v) largest_change = std::max(largest_change, std::abs(stepped[v] - steady[v]));
  EXPECT_GT(largest_change, 0.1);
}

}  // namespace
}  // namespace hydrodda::hydro
