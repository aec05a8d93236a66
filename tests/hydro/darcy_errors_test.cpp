// Bad input and failed solves are reported as exceptions with a clear message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <limits>
#include <string>
#include <vector>

#include "flow_test_meshes.hpp"
#include "hydro/darcy_solver.hpp"
#include "hydro/flow_failure.hpp"
#include "hydro/p1_element.hpp"
#include "hydro/region_permeability.hpp"

namespace hydrodda::hydro {
namespace {

template <class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

DarcyProblem make_problem(std::vector<BoundaryCondition> conditions) {
  DarcyProblem p;
  p.boundaries = std::move(conditions);
  return p;
}

const mesh::TriangleMesh& square() {
  static const auto m = testing::make_rectangle_mesh(1.0, 1.0, 0.2);
  return m;
}

TEST(DarcyErrors, NothingFixesTheHead) {
  const auto message = message_of([] {
    DarcySolver s(square(), make_problem({{"left", BoundaryKind::flux, -1e-6}}));
  });
  EXPECT_NE(message.find("nothing fixes the head"), std::string::npos) << message;
}

TEST(DarcyErrors, UnknownBoundaryIsNamed) {
  const auto message = message_of([] {
    DarcySolver s(square(), make_problem({{"inlet", BoundaryKind::head, 1.0}}));
  });
  EXPECT_NE(message.find("'inlet'"), std::string::npos) << message;
}

TEST(DarcyErrors, NonPositiveOrNanPermeabilityIsNamed) {
  DarcySolver solver(square(), make_problem({{"left", BoundaryKind::head, 1.0}}));
  std::vector<double> k(square().triangles.size(), 1e-12);
  k[3] = 0.0;
  EXPECT_NE(message_of([&] { solver.solve(k); }).find("triangle 3 is not positive"), std::string::npos);
  k[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message_of([&] { solver.solve(k); }).find("triangle 3 is not finite"), std::string::npos);
  k.pop_back();
  EXPECT_NE(message_of([&] { solver.solve(k); }).find("permeabilities for"), std::string::npos);
  std::vector<PermeabilityTensor> tensor(square().triangles.size(), {1e-12, 2e-12, 1e-12});
  EXPECT_NE(message_of([&] { solver.solve(tensor); }).find("not positive (definite)"), std::string::npos);
}

// Two triangles sharing no node; only the first touches the fixed boundary, so the second
// floats: its 3×3 block is singular (rows sum to zero) and the solver must say so.
TEST(DarcyErrors, FloatingPartIsASingularSystem) {
  mesh::TriangleMesh m;
  m.nodes = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {3, 0}, {2, 1}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  m.region = {0, 0};
  m.region_names = {"domain"};
  m.boundary_names = {"left"};
  m.boundary_edges = {{{2, 0}, 0}};
  EXPECT_THROW(DarcySolver(m, make_problem({{"left", BoundaryKind::head, 1.0}})), SingularSystem);
  const std::string message = message_of([&] { DarcySolver(m, make_problem({{"left", BoundaryKind::head, 1.0}})); });
  EXPECT_NE(message.find("the part of the mesh around node 3 (2.000000, 0.000000) touches no fixed-head boundary"),
            std::string::npos) << message;
}

// A solver whose factorisation always fails, in linear algebra's words, as CHOLMOD's does
// near jacking (a contrast of 1e20 between an open joint and the rock).
class FailingSolver : public numerics::SparseCholesky {
 public:
  void analyse(const SparseMatrix&) override {}
  void factorize(const SparseMatrix&) override {
    throw SingularSystem("CHOLMOD: the matrix is singular or not positive definite");
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return b; }
  std::string name() const override { return "failing"; }
};

// The permeability of the left-fixed square: 1e-12 m² everywhere, 1e-2 m² in one triangle
// (the open joint), and 1e-31 m² in the triangles whose centroid lies between x = tight_from
// and tight_to (none by default).
std::vector<double> joint_and_rock(double tight_from = 2.0, double tight_to = 2.0) {
  std::vector<double> k(square().triangles.size(), 1e-12);
  k[5] = 1e-2;
  for (int t = 0; t < square().triangle_count(); ++t) {
    const double x = mesh::triangle_centroid(square(), t).x;
    if (x >= tight_from && x <= tight_to) k[t] = 1e-31;
  }
  return k;
}

TEST(DarcyErrors, AFailedFactorisationNamesThePermeabilityContrast) {
  // Every part of the mesh reaches the fixed head through rock of 1e-12 m²: the message gives the
  // contrast the solve met and where, no linear-algebra words, and no hint about connectivity,
  // which is not the cause.
  DarcySolver solver(square(), make_problem({{"left", BoundaryKind::head, 1.0}}), std::make_unique<FailingSolver>());
  const std::vector<double> k = joint_and_rock();
  const std::string message = message_of([&] { solver.solve(k); });
  const geometry::Point joint = mesh::triangle_centroid(square(), 5);
  char where[64];
  std::snprintf(where, sizeof where, "(element 5 at (%.3g, %.3g))", joint.x, joint.y);
  EXPECT_NE(message.find("the flow solve failed (its matrix could not be factored): the permeability spans 1e-12 m²"),
            std::string::npos) << message;
  EXPECT_NE(message.find(std::string("to 0.01 m² ") + where), std::string::npos) << message;
  EXPECT_NE(message.find("a contrast of 1e+10"), std::string::npos) << message;
  EXPECT_EQ(message.find("CHOLMOD"), std::string::npos) << message;
  EXPECT_EQ(message.find("positive definite"), std::string::npos) << message;
  EXPECT_EQ(message.find("fixed-head boundary"), std::string::npos) << message;
  EXPECT_THROW(solver.solve(k), FlowSolveFailed);
  // The same through the kept factor's path (a coupling pass).
  EXPECT_EQ(message_of([&] { solver.solve_reusing_factor(k, {}); }), message);
}

TEST(DarcyErrors, TheConnectivityHintIsGivenOnlyWhereItIsTrue) {
  // A band of 1e-31 m² across the square (elements of 0.2 m: wider than one, so that no node
  // has elements on both sides of it), under 1e-16 of the largest permeability: the right part
  // reaches the fixed head at the left only through it, which round-off loses.
  DarcySolver solver(square(), make_problem({{"left", BoundaryKind::head, 1.0}}), std::make_unique<FailingSolver>());
  const std::string message = message_of([&] { solver.solve(joint_and_rock(0.25, 0.75)); });
  EXPECT_NE(message.find("past the 1e16 that double precision resolves"), std::string::npos) << message;
  EXPECT_NE(message.find("reaches a fixed-head boundary only through elements whose permeability is under 1e-16 of "
                         "the largest"),
            std::string::npos) << message;
  // Every part of the mesh reaches the fixed head: ill-conditioned, which is said, and not
  // disconnected, which no hint suggests.
  EXPECT_NE(message.find("; the system is ill-conditioned, not disconnected: the part of the mesh around node "),
            std::string::npos) << message;
  EXPECT_EQ(message.find("touches no fixed-head boundary"), std::string::npos) << message;
  EXPECT_EQ(message.find("is every part of the mesh connected"), std::string::npos) << message;
}

// A part of the mesh with no fixed head at all is disconnected, whatever the permeability: the
// message names its node and says so, and no contrast is blamed (1e-12 to 1e-12: none past
// 1e16). The assembler refuses such a mesh when it is set up, naming the node the same way.
TEST(DarcyErrors, ADisconnectedPartIsToldApartFromAnIllConditionedOne) {
  mesh::TriangleMesh m;
  m.nodes = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {3, 0}, {2, 1}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  const std::vector<double> k(2, 1e-12);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> fixed_head{1.0, nan, 1.0, nan, nan, nan};
  const std::string message = describe_flow_failure(m, k, fixed_head, "its matrix could not be factored");
  EXPECT_EQ(message,
            "the flow solve failed (its matrix could not be factored): the permeability spans 1e-12 m² (element 0 at "
            "(0.333, 0.333)) to 1e-12 m² (element 0 at (0.333, 0.333)), a contrast of 1; the part of the mesh around "
            "node 3 (2, 0) touches no fixed-head boundary: its head is undetermined");
  EXPECT_EQ(message.find("ill-conditioned"), std::string::npos) << message;
}

// Hand-computed element matrix of the right triangle (0,0), (1,0), (0,1) with K = I:
// ∇φ = (−1,−1), (1,0), (0,1), area ½ ⇒ K_e = ½ [[2,−1,−1],[−1,1,0],[−1,0,1]].
TEST(P1Element, RightTriangleMatrixIsExact) {
  const auto ke = compute_element_matrix({0, 0}, {1, 0}, {0, 1}, {1.0, 0.0, 1.0});
  const double expected[3][3] = {{1.0, -0.5, -0.5}, {-0.5, 0.5, 0.0}, {-0.5, 0.0, 0.5}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(ke[i][j], expected[i][j]) << i << "," << j;
  // Anisotropic K = [[2, 1], [1, 3]]: K_e(1,2) = ½ (K∇φ_2)·∇φ_1 = ½ (1, 3)·(1, 0) = ½.
  const auto ka = compute_element_matrix({0, 0}, {1, 0}, {0, 1}, {2.0, 1.0, 3.0});
  EXPECT_EQ(ka[1][2], 0.5);
  EXPECT_EQ(ka[2][1], 0.5);
  EXPECT_EQ(ka[1][1], 1.0);  // ½ (2, 1)·(1, 0)
  EXPECT_EQ(ka[2][2], 1.5);  // ½ (1, 3)·(0, 1)
}

// Determinism: the same input gives bit-identical heads from two solver objects.
TEST(DarcySolver, RepeatedSolvesAreBitIdentical) {
  const auto problem = make_problem({{"left", BoundaryKind::head, 1.0}, {"bottom", BoundaryKind::head, 0.0}});
  std::vector<double> k(square().triangles.size());
  for (std::size_t t = 0; t < k.size(); ++t) k[t] = 1e-12 * (1.0 + static_cast<double>(t % 7));
  DarcySolver a(square(), problem), b(square(), problem);
  const auto sa = a.solve(k), sb = b.solve(k), sa2 = a.solve(k);
  EXPECT_EQ(sa.head, sb.head);
  EXPECT_EQ(sa.head, sa2.head);
  EXPECT_LE(sa.balance_error, 1e-10);
}

// New boundary values on a solver already set up give the heads a solver built with them
// gives, bit for bit (the same fixed nodes, pattern and factorisation order); a change of the
// kind or of the boundaries named is refused, and the solver keeps its conditions.
TEST(DarcySolver, NewBoundaryValuesSolveAsAFreshSolver) {
  std::vector<double> k(square().triangles.size());
  for (std::size_t t = 0; t < k.size(); ++t) k[t] = 1e-12 * (1.0 + static_cast<double>(t % 5));
  DarcySolver changed(square(), make_problem({{"left", BoundaryKind::head, 1.0}, {"right", BoundaryKind::pressure, 0.0}}));
  changed.solve(k);
  const std::vector<BoundaryCondition> raised{{"left", BoundaryKind::head, 7.5}, {"right", BoundaryKind::pressure, 2e4}};
  changed.set_boundary_values(raised);
  DarcySolver fresh(square(), make_problem(raised));
  const FlowSolution a = changed.solve(k), b = fresh.solve(k);
  EXPECT_EQ(a.head, b.head);
  EXPECT_EQ(a.pressure, b.pressure);
  EXPECT_EQ(changed.reference_head(), 7.5);

  const std::string kind = message_of([&] {
    changed.set_boundary_values(std::vector<BoundaryCondition>{{"left", BoundaryKind::flux, 1e-6},
                                                               {"right", BoundaryKind::pressure, 0.0}});
  });
  EXPECT_NE(kind.find("only the values"), std::string::npos) << kind;
  const std::string fewer = message_of([&] {
    changed.set_boundary_values(std::vector<BoundaryCondition>{{"left", BoundaryKind::head, 1.0}});
  });
  EXPECT_NE(fewer.find("only the values"), std::string::npos) << fewer;
  EXPECT_EQ(changed.solve(k).head, b.head);
}

}  // namespace
}  // namespace hydrodda::hydro

namespace hydrodda::hydro {
namespace {

TEST(RegionPermeability, AssignsPerRegionAndNamesGaps) {
  mesh::TriangleMesh m;
  m.nodes = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.region = {0, 1};
  m.region_names = {"domain", "seam"};
  const auto k = assign_region_permeability(m, {{"domain", 1e-15}, {"seam", 1e-9}});
  EXPECT_EQ(k, (std::vector<double>{1e-15, 1e-9}));
  EXPECT_NE(message_of([&] { assign_region_permeability(m, {{"seam", 1e-9}}); }).find("'domain'"),
            std::string::npos);
  EXPECT_NE(message_of([&] { assign_region_permeability(m, {{"core", 1e-9}}); }).find("'core'"),
            std::string::npos);
  EXPECT_THROW(assign_region_permeability(m, {{"domain", -1.0}, {"seam", 1.0}}), std::runtime_error);
}

}  // namespace
}  // namespace hydrodda::hydro
