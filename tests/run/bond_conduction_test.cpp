// Broken bonds as hydraulic fractures (docs/dda.md, "Bonds"; run/sub_blocks.hpp
// network_with_bond_faces, coupling/embedded_joints.hpp, coupling/pressure_forces.hpp):
// - a bar of two sub-blocks whose bonded face is broken conducts as the same bar cut by a
//   joint of that type: the same crossings, apertures and permeability tensors, bit for bit
//   (an exact identity: the same faces, the same law), and so the same flow along it;
// - while the bond is intact the face is rock: no crossing conducts, every element keeps the
//   matrix permeability exactly, and the flow along the bar is the matrix's k ρg/μ Δh/L × width
//   (a linear head, exact on any P1 mesh, to 1e-12 relative);
// - the fluid loads a broken bond's faces as a joint's, bit for bit, and an intact bond's not
//   at all, the two sub-blocks then taking together the loads of the block they tessellate
//   (resultant and moment to 1e-12 of the load).

#include <gtest/gtest.h>

#include <cmath>

#include "../coupling/structured_mesh.hpp"
#include "coupling/embedded_joints.hpp"
#include "coupling/pressure_forces.hpp"
#include "geometry/block_network.hpp"
#include "hydro/darcy_solver.hpp"
#include "run/model_geometry.hpp"
#include "run/sub_blocks.hpp"

namespace hydrodda::run {
namespace {

using geometry::Point;
using geometry::Polygon;

constexpr double kFace = 0.45;        // the face between the two halves of the bar, y = 0.45
constexpr double kMatrix = 1.0e-18;   // m²
const hydro::JointApertureLaw kLaw{1.0e-5, 0.0, 0.0};  // a residual aperture, no closure

mesh::TriangleMesh make_bar_mesh() {
  mesh::TriangleMesh m = testing::make_rectangle_mesh(0.0, 0.0, 1.0, 1.0, 8, 8);
  m.boundary_names = {"left", "right"};
  for (const auto& e : mesh::find_boundary_edges(m.triangles)) {
    const Point a = m.nodes[e[0]], b = m.nodes[e[1]];
    int name = mesh::BoundaryEdge::kUnnamed;
    if (a.x == 0.0 && b.x == 0.0) name = 0;
    if (a.x == 1.0 && b.x == 1.0) name = 1;
    m.boundary_edges.push_back({e, name});
  }
  return m;
}

// The unit bar cut along y = 0.45 by a joint (fracture 0).
ModelGeometry jointed_bar() {
  ModelGeometry g;
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.traces = {{{{0.0, kFace}, {1.0, kFace}}, {}}};
  g.traces = request.traces;
  g.network = geometry::build_block_network(request);
  return g;
}

// The same two blocks as sub-blocks of an uncut bar, their shared face bond 0 (of type 0).
ModelGeometry bonded_bar() {
  ModelGeometry g = jointed_bar();
  g.traces.clear();
  g.network.faces.clear();
  g.edge_bonds.resize(g.network.blocks.size());
  for (std::size_t b = 0; b < g.network.blocks.size(); ++b) {
    for (int& f : g.network.edge_fractures[b]) {
      g.edge_bonds[b].push_back(f == 0 ? 0 : -1);
      if (f == 0) f = -1;
    }
  }
  g.bond_types = {0};
  return g;
}

// The blocks pulled apart across the face by `opening` (the upper one moved up).
std::vector<Polygon> opened(const geometry::BlockNetwork& network, double opening) {
  std::vector<Polygon> blocks = network.blocks;
  for (Polygon& p : blocks)
    if (geometry::centroid(p).y > kFace)
      for (Point& v : p) v.y += opening;
  return blocks;
}

double flow_along(const mesh::TriangleMesh& mesh, const std::vector<hydro::PermeabilityTensor>& k) {
  hydro::DarcyProblem problem;
  problem.boundaries = {{"left", hydro::BoundaryKind::head, 1.0}, {"right", hydro::BoundaryKind::head, 0.0}};
  hydro::DarcySolver solver(mesh, problem);
  const hydro::FlowSolution solution = solver.solve(k);
  return std::abs(solution.boundary_flows.at(0).flow);  // "left": inflow
}

TEST(BondConduction, ABrokenBondConductsAsAJointOfItsTypeAndAnIntactOneAsRock) {
  const mesh::TriangleMesh mesh = make_bar_mesh();
  const ModelGeometry jointed = jointed_bar();
  const ModelGeometry bonded = bonded_bar();
  const geometry::BlockNetwork bond_network = network_with_bond_faces(bonded);
  ASSERT_EQ(bond_network.faces.size(), 1u);
  EXPECT_EQ(bond_network.faces[0].fracture, 0);  // no traces: the bond is fracture 0

  const coupling::EmbeddedJoints joint(mesh, jointed.network, coupling::JointApertureLaws({kLaw}, {0}));
  const coupling::EmbeddedJoints bond(mesh, bond_network, coupling::JointApertureLaws({kLaw}, {0}), 0);
  ASSERT_EQ(joint.crossings().size(), bond.crossings().size());
  ASSERT_FALSE(joint.crossings().empty());
  EXPECT_EQ(joint.zone(), bond.zone());  // the fixed mesh's crossings, found from the start

  const double opening = 2.0e-4;
  const std::vector<double> matrix(static_cast<std::size_t>(mesh.triangle_count()), kMatrix);
  const std::vector<double> joint_apertures = joint.apertures(opened(jointed.network, opening), {}, 1e-9);
  const std::vector<char> broken{1}, intact{0};
  const std::vector<double> broken_apertures = bond.apertures(opened(bonded.network, opening), {}, 1e-9, broken);
  for (double a : joint_apertures) EXPECT_NEAR(a, 1.0e-5 + opening, 1e-15);  // a_r + opening
  EXPECT_EQ(broken_apertures, joint_apertures);
  const auto k_joint = joint.permeability(matrix, joint_apertures);
  const auto k_broken = bond.permeability(matrix, broken_apertures);
  for (std::size_t e = 0; e < k_joint.size(); ++e) {
    EXPECT_EQ(k_broken[e].xx, k_joint[e].xx) << e;
    EXPECT_EQ(k_broken[e].xy, k_joint[e].xy) << e;
    EXPECT_EQ(k_broken[e].yy, k_joint[e].yy) << e;
  }
  EXPECT_EQ(flow_along(mesh, k_broken), flow_along(mesh, k_joint));

  // Intact: rock, however far the faces stand apart (a bond's springs stretch under tension).
  const std::vector<double> intact_apertures = bond.apertures(opened(bonded.network, opening), {}, 1e-9, intact);
  for (double a : intact_apertures) EXPECT_EQ(a, 0.0);
  const auto k_intact = bond.permeability(matrix, intact_apertures);
  for (const hydro::PermeabilityTensor& k : k_intact) {
    EXPECT_EQ(k.xx, kMatrix);
    EXPECT_EQ(k.xy, 0.0);
    EXPECT_EQ(k.yy, kMatrix);
  }
  // q = k ρg/μ Δh/L × width, with Δh = 1 m over L = 1 m and a width of 1 m.
  const double matrix_flow = kMatrix * 1000.0 * 9.81 / 1.0e-3;
  EXPECT_NEAR(flow_along(mesh, k_intact), matrix_flow, 1e-12 * matrix_flow);
  // Broken, the joint's a³/12 carries it: (1.0e-5 + 2e-4)³/12 ≫ the matrix's 1e-18 m².
  EXPECT_GT(flow_along(mesh, k_broken), 1e5 * matrix_flow);
  // The state of every bond is needed.
  EXPECT_THROW(static_cast<void>(bond.apertures(bonded.network.blocks, {}, 1e-9)), std::invalid_argument);
}

// Per block, per edge: sealed where the edge is an intact bond.
std::vector<std::vector<char>> sealed_bonds(const ModelGeometry& g) {
  std::vector<std::vector<char>> sealed;
  for (const std::vector<int>& edges : g.edge_bonds) {
    sealed.emplace_back();
    for (int bond : edges) sealed.back().push_back(bond >= 0 ? 1 : 0);
  }
  return sealed;
}

TEST(BondConduction, TheFluidLoadsABrokenBondAsAJointAndAnIntactOneNotAtAll) {
  const mesh::TriangleMesh mesh = make_bar_mesh();
  const ModelGeometry bonded = bonded_bar();
  // A pressure that varies in x and y: p = 1e6 (1 + x + 2y) Pa at the nodes (P1 exact).
  std::vector<double> pressure;
  for (const Point& n : mesh.nodes) pressure.push_back(1.0e6 * (1.0 + n.x + 2.0 * n.y));
  const coupling::FacePressureLoads loads(mesh);
  const std::vector<Polygon>& blocks = bonded.network.blocks;
  for (const double alpha : {0.0, 0.6}) {
    const std::vector<double> biot(blocks.size(), alpha);
    const auto joint = loads.compute(blocks, pressure, biot);  // every edge a face
    const auto broken = loads.compute(blocks, pressure, biot, std::vector<std::vector<char>>(blocks.size()));
    EXPECT_EQ(broken, joint) << alpha;
    const auto intact = loads.compute(blocks, pressure, biot, sealed_bonds(bonded));
    // The two sub-blocks together: the loads of the uncut bar (resultant and moment about 0).
    const Polygon bar{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const auto whole = loads.compute(std::vector<Polygon>{bar}, pressure, std::vector<double>{alpha});
    Point force{}, whole_force{};
    double moment = 0.0, whole_moment = 0.0;
    for (std::size_t b = 0; b < blocks.size(); ++b)
      for (std::size_t v = 0; v < blocks[b].size(); ++v) {
        force += intact[b][v];
        moment += geometry::cross(blocks[b][v], intact[b][v]);
        // The bonded face takes nothing: its end vertices carry the outer faces' loads only.
      }
    for (std::size_t v = 0; v < bar.size(); ++v) {
      whole_force += whole[0][v];
      whole_moment += geometry::cross(bar[v], whole[0][v]);
    }
    const double scale = (1.0 - alpha) * 4.0e6;  // the faces' load, about (1 − α) p × perimeter
    EXPECT_NEAR(force.x, whole_force.x, 1e-12 * scale) << alpha;
    EXPECT_NEAR(force.y, whole_force.y, 1e-12 * scale) << alpha;
    EXPECT_NEAR(moment, whole_moment, 1e-12 * scale) << alpha;
    // Each sub-block alone: its share of the bar's faces, the bonded face none. Sealed, the
    // lower one's loads are the jointed ones less the face's (which pushes it down, −y).
    const std::size_t lower = geometry::centroid(blocks[0]).y < kFace ? 0 : 1;
    Point lower_intact{}, lower_joint{};
    for (std::size_t v = 0; v < blocks[lower].size(); ++v) {
      lower_intact += intact[lower][v];
      lower_joint += joint[lower][v];
    }
    if (alpha < 1.0) EXPECT_GT(lower_intact.y - lower_joint.y, 0.9 * (1.0 - alpha) * 1.0e6) << alpha;
  }
}

}  // namespace
}  // namespace hydrodda::run
