// Bonded sub-blocks against the continuum, by an exact identity: triangle sub-blocks bonded
// along every shared face are the constant-strain-triangle (CST) finite elements of the same
// triangles in the limit of stiff bonds.
//
// A DDA block's displacement u = T(x, y) D (Shi 1988) is complete-linear in x and y (six
// unknowns, the six coefficients of a linear field), its strain energy area × εᵀ E ε: on a
// triangle, exactly the CST's. Bonds hold each shared face's two ends together in both
// directions, which for two linear fields along a straight face is continuity along all of
// it. So a bonded triangle mesh under any load tends, as its springs stiffen, to the CST
// solution of the same mesh, nodal displacement for nodal displacement, and its error falls as
// the springs' compliance against the rock's: O(E / p) (a spring of p l / l̄ in series with
// cells of stiffness ~E).
//
// The load here is not uniform: a cantilever 4 m × 1 m of 32 triangles, clamped at x = 0
// (fixed points at its left nodes), sheared down at its free end x = 4 m by a uniform traction
// (bending and shear, the stress varying over the cells). The CST reference is assembled and
// solved below (plane strain, the same nodes clamped, the traction's consistent nodal loads
// τ l / 2 to each end of a loaded face). The DDA runs static steps to rest, with penalty
// contacts (no Lagrangian iterations, so that the rate is the springs' own).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "dda/system.hpp"

namespace hydrodda::dda {
namespace {

constexpr double kYoung = 1.0e10;
constexpr double kPoisson = 0.25;
constexpr double kShear = -1.0e3;  // Pa, on the free end (down): a tip deflection of ~1e-5 m
constexpr double kLength = 4.0;
constexpr double kHeight = 1.0;
constexpr int kCellsX = 8;
constexpr int kCellsY = 2;

struct TriangleMesh {
  std::vector<Point> nodes;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise
};

// Squares of 0.5 m, each cut along the diagonal that alternates from square to square.
TriangleMesh make_cantilever_mesh() {
  TriangleMesh mesh;
  const double hx = kLength / kCellsX;
  const double hy = kHeight / kCellsY;
  for (int j = 0; j <= kCellsY; ++j)
    for (int i = 0; i <= kCellsX; ++i) mesh.nodes.push_back({i * hx, j * hy});
  const auto id = [](int i, int j) { return j * (kCellsX + 1) + i; };
  for (int j = 0; j < kCellsY; ++j)
    for (int i = 0; i < kCellsX; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else {
        mesh.triangles.push_back({a, b, d});
        mesh.triangles.push_back({b, c, d});
      }
    }
  return mesh;
}

bool on_free_end(const TriangleMesh& mesh, int a, int b) {
  return mesh.nodes[a].x > kLength - 1e-9 && mesh.nodes[b].x > kLength - 1e-9;
}

// Plane-strain elasticity matrix (σxx, σyy, τxy from εx, εy, γxy).
Eigen::Matrix3d plane_strain_elasticity() {
  const double f = kYoung / ((1.0 + kPoisson) * (1.0 - 2.0 * kPoisson));
  Eigen::Matrix3d e;
  e << 1.0 - kPoisson, kPoisson, 0.0, kPoisson, 1.0 - kPoisson, 0.0, 0.0, 0.0, 0.5 - kPoisson;
  return f * e;
}

// The CST solution: K = Σ A Bᵀ E B over the triangles (B the constant strain–displacement
// matrix of linear shape functions), the left nodes clamped, the end's traction as consistent
// nodal loads. Two unknowns (u, v) a node.
Eigen::VectorXd solve_cst(const TriangleMesh& mesh) {
  const int n = static_cast<int>(mesh.nodes.size());
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * n);
  const Eigen::Matrix3d e = plane_strain_elasticity();
  for (const std::array<int, 3>& t : mesh.triangles) {
    const Point p[3] = {mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]};
    const double area2 = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    Eigen::Matrix<double, 3, 6> b = Eigen::Matrix<double, 3, 6>::Zero();
    for (int k3 = 0; k3 < 3; ++k3) {
      const Point q = p[(k3 + 1) % 3], r = p[(k3 + 2) % 3];
      const double dndx = (q.y - r.y) / area2, dndy = (r.x - q.x) / area2;
      b(0, 2 * k3) = dndx;
      b(1, 2 * k3 + 1) = dndy;
      b(2, 2 * k3) = dndy;
      b(2, 2 * k3 + 1) = dndx;
    }
    const Eigen::Matrix<double, 6, 6> ke = 0.5 * area2 * b.transpose() * e * b;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) k(2 * t[r / 2] + r % 2, 2 * t[c / 2] + c % 2) += ke(r, c);
    for (int k3 = 0; k3 < 3; ++k3) {
      const int a = t[k3], bb = t[(k3 + 1) % 3];
      if (!on_free_end(mesh, a, bb)) continue;
      const double half = 0.5 * std::abs(mesh.nodes[bb].y - mesh.nodes[a].y) * kShear;
      f(2 * a + 1) += half;
      f(2 * bb + 1) += half;
    }
  }
  for (int i = 0; i < n; ++i)
    if (mesh.nodes[i].x < 1e-9)
      for (int c = 0; c < 2; ++c) {  // clamped: the row and column replaced by the identity
        k.row(2 * i + c).setZero();
        k.col(2 * i + c).setZero();
        k(2 * i + c, 2 * i + c) = 1.0;
        f(2 * i + c) = 0.0;
      }
  return k.ldlt().solve(f);
}

// The same triangles as bonded sub-blocks of one strong bond type, the left nodes held by
// fixed points (one on each sub-block that has the node), the end's faces sheared by kShear.
ModelDefinition make_bonded_cantilever(const TriangleMesh& mesh, double penalty) {
  ModelDefinition m;
  m.materials = {Material{2500.0, kYoung, kPoisson}};
  m.joint = {30.0, 0.0, 0.0};
  m.joint_types = {Joint{30.0, 1.0e12, 1.0e12}};
  std::map<std::pair<int, int>, int> bond_of_face;
  for (std::size_t b = 0; b < mesh.triangles.size(); ++b) {
    const std::array<int, 3>& t = mesh.triangles[b];
    BlockDefinition block{{mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]}, 0, false};
    block.edge_joints.assign(3, 1);
    block.edge_bonds.assign(3, -1);
    for (int k3 = 0; k3 < 3; ++k3) {
      const int a = t[k3], c = t[(k3 + 1) % 3];
      const std::pair<int, int> face{std::min(a, c), std::max(a, c)};
      const auto [it, fresh] = bond_of_face.emplace(face, static_cast<int>(bond_of_face.size()));
      block.edge_bonds[static_cast<std::size_t>(k3)] = it->second;  // unpaired ids removed below
      if (on_free_end(mesh, a, c))
        m.tractions.push_back({static_cast<int>(b), k3, 0.0, 0.0, kShear, kShear});
      if (mesh.nodes[a].x < 1e-9) m.fixed_points.push_back({static_cast<int>(b), mesh.nodes[a]});
    }
    m.blocks.push_back(std::move(block));
  }
  // Faces on the outline belong to one sub-block: no bond. Renumber the shared ones 0, 1, ...
  std::map<int, int> uses, renumbered;
  for (const BlockDefinition& b : m.blocks)
    for (int id : b.edge_bonds) ++uses[id];
  for (const auto& [id, count] : uses)
    if (count == 2) renumbered.emplace(id, static_cast<int>(renumbered.size()));
  for (BlockDefinition& b : m.blocks)
    for (int& id : b.edge_bonds) id = renumbered.count(id) ? renumbered.at(id) : -1;
  m.settings.analysis = Analysis::static_;
  m.settings.gravity = {0.0, 0.0};
  m.settings.time_step = 1.0;
  m.settings.contact = ContactMethod::penalty;
  m.settings.penalty = penalty;
  return m;
}

// The largest difference between a sub-block's vertex displacement and the CST's at its node,
// over every vertex of every sub-block, ÷ the CST's largest nodal displacement.
double relative_difference_from_cst(double penalty) {
  const TriangleMesh mesh = make_cantilever_mesh();
  const Eigen::VectorXd cst = solve_cst(mesh);
  double largest = 0.0;
  for (int i = 0; i < cst.size() / 2; ++i) largest = std::max(largest, std::hypot(cst(2 * i), cst(2 * i + 1)));
  System system(make_bonded_cantilever(mesh, penalty));
  // Static steps of 1 s (the inertia 2M/Δt² some 1e-6 of the cells' stiffness): the first
  // takes the load, the next bring the rest of the way to rest; at 100 E a few vertex–vertex
  // contacts open and shut from step to step by under 1e-9 m, so a count of steps, not
  // run_to_equilibrium, whose rest is to 1e-9 of the model's size.
  StepReport last = system.run_steps(20);
  EXPECT_LT(last.max_displacement, 1e-4 * largest) << "not settled at p = " << penalty;
  double worst = 0.0;
  for (std::size_t b = 0; b < mesh.triangles.size(); ++b)
    for (int k3 = 0; k3 < 3; ++k3) {
      const int node = mesh.triangles[b][static_cast<std::size_t>(k3)];
      const Point moved = system.polygon(static_cast<int>(b))[static_cast<std::size_t>(k3)] - mesh.nodes[node];
      worst = std::max(worst, std::hypot(moved.x - cst(2 * node), moved.y - cst(2 * node + 1)));
    }
  return worst / largest;
}

TEST(BondedContinuum, BondedTrianglesTendToTheirCstSolutionAsTheBondsStiffen) {
  // O(E/p): each tenfold stiffer penalty divides the difference by ten (within [7, 13]: the
  // next term's share at 100 E), and at 10^5 E the sub-blocks are the CST's to 1e-4.
  const double at_100 = relative_difference_from_cst(1.0e2 * kYoung);
  const double at_1000 = relative_difference_from_cst(1.0e3 * kYoung);
  const double at_10000 = relative_difference_from_cst(1.0e4 * kYoung);
  const double at_100000 = relative_difference_from_cst(1.0e5 * kYoung);
  // Measured: 7.9e-3, 7.7e-4, 7.7e-5, 8.1e-6 of the largest nodal displacement (1.6e-5 m).
  EXPECT_GT(at_100 / at_1000, 7.0);
  EXPECT_LT(at_100 / at_1000, 13.0);
  EXPECT_GT(at_1000 / at_10000, 7.0);
  EXPECT_LT(at_1000 / at_10000, 13.0);
  EXPECT_LT(at_100000, 1.0e-4);
}

}  // namespace
}  // namespace hydrodda::dda
