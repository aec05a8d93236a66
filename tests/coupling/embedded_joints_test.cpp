// Joints as embedded fractures (coupling/embedded_joints.hpp, hydro::JointApertureLaw):
// - the Barton–Bandis law's values, a(σ) = a_r + V_m − σ V_m / (k_ni V_m + σ) (1e-15 relative);
// - the pieces of a face inside the elements add up to the face (1e-12 relative), along
//   element edges too, where each of the two elements takes half;
// - a joint in an all but impermeable matrix carries (ρg/μ)(a³/12) Δh/L exactly for a head
//   linear along it (the P1 identity Σ_e L_e ∂φ_i/∂s = 0 at every node off its ends): 1e-6
//   relative, the matrix's own share being 1e-8 of it;
// - its aperture follows the gauge (open: a(0) + opening) and the contact forces (closed:
//   σn = Σ F / closed length);
// - isotropic tensors solve bit for bit as the scalar permeabilities;
// - crossings of faces of two joint types each take their own type's law (exact: the law's own
//   values, bit for bit).

#include <gtest/gtest.h>

#include <cmath>

#include "coupling/embedded_joints.hpp"
#include "geometry/block_network.hpp"
#include "hydro/darcy_solver.hpp"
#include "hydro/permeability_law.hpp"
#include "structured_mesh.hpp"

namespace hydrodda::coupling {
namespace {

using geometry::Point;
using geometry::Polygon;

constexpr double kRhoGOverMu = 1000.0 * 9.81 / 1.0e-3;

TEST(JointApertureLaw, BartonBandisClosure) {
  const hydro::JointApertureLaw law{1.0e-5, 2.0e11, 1.0e-4};
  EXPECT_DOUBLE_EQ(law.at_zero_stress(), 1.1e-4);
  EXPECT_DOUBLE_EQ(law.closed(0.0), 1.1e-4);
  EXPECT_DOUBLE_EQ(law.closed(-5.0e6), 1.1e-4);  // tension does not squeeze it
  for (const double sigma : {1.0e5, 5.0e6, 2.0e7, 1.0e9}) {
    const double expected = 1.0e-5 + 1.0e-4 - sigma * 1.0e-4 / (2.0e11 * 1.0e-4 + sigma);
    EXPECT_NEAR(law.closed(sigma), expected, 1e-15 * expected) << sigma;
  }
  EXPECT_NEAR(law.closed(2.0e7), 6.0e-5, 1e-18);  // half the closure at σ = k_ni V_m
  // Towards the residual aperture: a − a_r = V_m k_ni V_m / (k_ni V_m + σ), 2e-12 m at 1e15 Pa.
  EXPECT_NEAR(law.closed(1.0e15) - 1.0e-5, 1.0e-4 * 2.0e7 / (2.0e7 + 1.0e15), 1e-17);
  EXPECT_DOUBLE_EQ(law.open(2.0e-4), 3.1e-4);
  const hydro::JointApertureLaw residual_only{1.0e-4, 0.0, 0.0};
  EXPECT_EQ(residual_only.closed(1.0e8), 1.0e-4);
  EXPECT_EQ(residual_only.open(1.0e-3), 1.1e-3);
}

struct Model {
  mesh::TriangleMesh mesh;
  geometry::BlockNetwork network;
};

// A unit square on a structured n × n mesh, cut by one joint from (0, y0) to (1, y1), no
// initial aperture; boundaries "left" and "right" named.
Model make_model(int n, double y0, double y1) {
  Model m;
  m.mesh = testing::make_rectangle_mesh(0.0, 0.0, 1.0, 1.0, n, n);
  m.mesh.boundary_names = {"left", "right"};
  for (const auto& e : mesh::find_boundary_edges(m.mesh.triangles)) {
    const Point a = m.mesh.nodes[e[0]], b = m.mesh.nodes[e[1]];
    int name = mesh::BoundaryEdge::kUnnamed;
    if (a.x == 0.0 && b.x == 0.0) name = 0;
    if (a.x == 1.0 && b.x == 1.0) name = 1;
    m.mesh.boundary_edges.push_back({e, name});
  }
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.traces = {{{{0.0, y0}, {1.0, y1}}, {}}};
  m.network = geometry::build_block_network(request);
  return m;
}

double crossed_length(const EmbeddedJoints& joints) {
  double total = 0.0;
  for (const JointCrossing& c : joints.crossings()) total += c.length;
  return total;
}

TEST(EmbeddedJoints, PiecesAddUpToTheFaceAcrossAndAlongElements) {
  for (const auto& [y0, y1] : {std::pair{0.3, 0.7}, std::pair{0.5, 0.5}, std::pair{0.05, 0.95}}) {
    const Model m = make_model(10, y0, y1);
    ASSERT_EQ(m.network.faces.size(), 1u);
    const EmbeddedJoints joints(m.mesh, m.network, {1.0e-4, 0.0, 0.0});
    const double length = std::hypot(1.0, y1 - y0);
    EXPECT_NEAR(crossed_length(joints), length, 1e-12 * length) << y0 << " " << y1;
    // The zone holds every crossed element.
    for (const JointCrossing& c : joints.crossings()) EXPECT_TRUE(joints.zone()[c.element]);
  }
  // y = 0.5 runs along element edges: every piece is half of an edge in each of two elements.
  const Model along = make_model(10, 0.5, 0.5);
  const EmbeddedJoints joints(along.mesh, along.network, {1.0e-4, 0.0, 0.0});
  EXPECT_EQ(joints.crossings().size(), 20u);
  for (const JointCrossing& c : joints.crossings()) EXPECT_NEAR(c.length, 0.05, 1e-14);
}

// Outflow through the right side of the joint's flow, heads 1 and 0 on the left and right.
double joint_outflow(const Model& m, double aperture, double k_matrix) {
  const EmbeddedJoints joints(m.mesh, m.network, {aperture, 0.0, 0.0});
  std::vector<double> iso(m.mesh.triangles.size(), k_matrix);
  const std::vector<double> apertures(joints.crossings().size(), aperture);
  hydro::DarcySolver solver(m.mesh, {{}, {{"left", hydro::BoundaryKind::head, 1.0}, {"right", hydro::BoundaryKind::head, 0.0}}});
  return solver.solve(joints.permeability(iso, apertures)).boundary_flow("right");
}

TEST(EmbeddedJoints, JointCarriesTheCubicLawOnEveryMesh) {
  const double a = 1.0e-4, k_matrix = 1.0e-25;
  for (const auto& [y0, y1] : {std::pair{0.3, 0.7}, std::pair{0.5, 0.5}, std::pair{0.37, 0.41}})
    for (const int n : {4, 9, 20}) {
      const Model m = make_model(n, y0, y1);
      const double length = std::hypot(1.0, y1 - y0);
      // Q = (ρg/μ)(a³/12) Δh / L, plus the matrix's (ρg/μ) k_m Δh (1e-8 of it).
      const double expected = kRhoGOverMu * (a * a * a / 12.0 / length + k_matrix);
      EXPECT_NEAR(joint_outflow(m, a, k_matrix), expected, 1e-6 * expected) << n << " " << y0 << " " << y1;
    }
}

// The block above the horizontal joint at y = 0.5 and its edge along it; −1s if none.
std::pair<int, int> upper_face(const Model& m) {
  for (std::size_t b = 0; b < m.network.blocks.size(); ++b)
    for (std::size_t e = 0; e < m.network.edge_fractures[b].size(); ++e)
      if (m.network.edge_fractures[b][e] == 0 && geometry::centroid(m.network.blocks[b]).y > 0.5)
        return {static_cast<int>(b), static_cast<int>(e)};
  return {-1, -1};
}

TEST(EmbeddedJoints, ApertureFollowsTheGaugeAndTheContactForces) {
  const Model m = make_model(8, 0.5, 0.5);
  const hydro::JointApertureLaw law{1.0e-5, 2.0e11, 1.0e-4};
  const EmbeddedJoints joints(m.mesh, m.network, law);
  std::vector<Polygon> blocks = m.network.blocks;
  // Closed and unloaded: a(0).
  for (double a : joints.apertures(blocks, {}, 1e-9)) EXPECT_DOUBLE_EQ(a, law.at_zero_stress());
  // Closed under 3 kN on the 1 m face, shared by two contacts: σn = 3 MPa.
  const auto [upper, edge] = upper_face(m);
  ASSERT_GE(upper, 0);
  const int lower = 1 - upper;
  std::vector<dda::ContactInfo> contacts{{{lower, 0, upper, edge}, dda::ContactState::locked, 0.0, 1.0e6},
                                         {{lower, 1, upper, edge}, dda::ContactState::locked, 0.0, 2.0e6},
                                         {{lower, 2, upper, edge}, dda::ContactState::open, -1e-3, 5.0e6}};
  for (double a : joints.apertures(blocks, contacts, 1e-9)) EXPECT_DOUBLE_EQ(a, law.closed(3.0e6));
  // The upper block lifted by 0.2 mm, its contacts open and carrying nothing: a(0) + 0.2 mm.
  for (Point& p : blocks[upper]) p.y += 2.0e-4;
  std::vector<dda::ContactInfo> lifted = contacts;
  for (dda::ContactInfo& c : lifted) {
    c.state = dda::ContactState::open;
    c.normal_force = 0.0;
  }
  for (double a : joints.apertures(blocks, lifted, 1e-9)) EXPECT_NEAR(a, law.open(2.0e-4), 1e-15);
  // The same gap while the face still carries its 3 kN: closed along its length under 3 MPa by
  // default (the face's force decides); open by its gap where each point decides.
  for (double a : joints.apertures(blocks, contacts, 1e-9)) EXPECT_DOUBLE_EQ(a, law.closed(3.0e6));
  hydro::JointApertureLaw local = law;
  local.opening = hydro::HydraulicOpening::local;
  const EmbeddedJoints by_point(m.mesh, m.network, local);
  for (double a : by_point.apertures(blocks, contacts, 1e-9)) EXPECT_NEAR(a, law.open(2.0e-4), 1e-15);
}

// A face left open at one end as a wedge while its other end carries the force (two blocks whose
// uniform strains differ: docs/coupling.md, "Joint hydraulic apertures"). The horizontal 1 m face
// at y = 0.5, the upper block turned about the face's left end so that the gap grows as
// w(x) = θ x, and 3 kN on the face. By default every crossing takes the closure under the mean
// stress 3 kN / 1 m = 3 MPa, the face's length being the crossings' (the wedge's gap not seen);
// with `local` each crossing whose gauge opens by more than the threshold takes a(0) + w there,
// and the others the closure under 3 kN over the closed crossings' length. Exact: the values are
// the law's own, compared bit for bit.
TEST(EmbeddedJoints, AWedgeThatCarriesAForceIsClosedAlongTheFaceByDefault) {
  const Model m = make_model(8, 0.5, 0.5);
  const hydro::JointApertureLaw law{1.0e-5, 2.0e11, 1.0e-4};
  hydro::JointApertureLaw local = law;
  local.opening = hydro::HydraulicOpening::local;
  const EmbeddedJoints by_face(m.mesh, m.network, law), by_point(m.mesh, m.network, local);
  std::vector<Polygon> blocks = m.network.blocks;
  const auto [upper, edge] = upper_face(m);
  ASSERT_GE(upper, 0);
  const double theta = 1.0e-4;  // rad: 0.1 mm at the right end
  for (Point& p : blocks[upper]) p = Point{p.x - theta * (p.y - 0.5), p.y + theta * p.x};
  const std::vector<dda::ContactInfo> contacts{{{1 - upper, 0, upper, edge}, dda::ContactState::locked, 0.0, 3.0e3}};
  const double threshold = 2.0e-5;
  const std::vector<double> face = by_face.apertures(blocks, contacts, threshold);
  const std::vector<double> point = by_point.apertures(blocks, contacts, threshold);
  double closed_length = 0.0;
  std::vector<double> gap(face.size());
  for (std::size_t c = 0; c < face.size(); ++c) {
    gap[c] = geometry::read_gauge(by_face.crossings()[c].gauge, blocks, m.network.blocks).opening;
    if (!(gap[c] > threshold)) closed_length += by_face.crossings()[c].length;
  }
  ASSERT_GT(closed_length, 0.1);
  ASSERT_LT(closed_length, 0.9);
  int open = 0;
  for (std::size_t c = 0; c < face.size(); ++c) {
    EXPECT_DOUBLE_EQ(face[c], law.closed(3.0e3 / crossed_length(by_face))) << c;
    if (gap[c] > threshold) {
      ++open;
      EXPECT_EQ(point[c], law.open(gap[c])) << c;
    } else {
      EXPECT_EQ(point[c], law.closed(3.0e3 / closed_length)) << c;
    }
  }
  EXPECT_GT(open, 0);
  EXPECT_NEAR(crossed_length(by_face), 1.0, 1e-12);
}

// Two horizontal joints, y = 0.3 of the default type and y = 0.7 of type 1 (a fault), on a
// structured mesh: every crossing of the lower takes the default law, every one of the upper the
// fault's, closed (a(0), then the closure under 3 MPa, σn = ΣF / closed length) and open
// (a(0) + w). The values are the laws' own, a_r + V_m − σ V_m/(k_ni V_m + σ) and a_r + V_m + w,
// compared bit for bit.
TEST(EmbeddedJoints, CrossingsOfTwoJointTypesTakeTheirOwnLaws) {
  Model m;
  m.mesh = testing::make_rectangle_mesh(0.0, 0.0, 1.0, 1.0, 8, 8);
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  request.traces = {{{{0.0, 0.3}, {1.0, 0.3}}, {}, 0}, {{{0.0, 0.7}, {1.0, 0.7}}, {}, 1}};
  m.network = geometry::build_block_network(request);
  ASSERT_EQ(m.network.blocks.size(), 3u);
  const hydro::JointApertureLaw joint{1.0e-5, 2.0e11, 1.0e-4}, fault{2.0e-4, 5.0e10, 3.0e-4};
  const EmbeddedJoints joints(m.mesh, m.network, JointApertureLaws({joint, fault}, {0, 1}));
  const auto law_of = [&](const JointCrossing& c) { return c.face.fracture == 0 ? joint : fault; };
  int on_fault = 0;
  for (const JointCrossing& c : joints.crossings()) on_fault += c.face.fracture == 1 ? 1 : 0;
  ASSERT_GT(on_fault, 0);
  ASSERT_LT(on_fault, static_cast<int>(joints.crossings().size()));

  std::vector<Polygon> blocks = m.network.blocks;
  const std::vector<double> unloaded = joints.apertures(blocks, {}, 1e-9);
  for (std::size_t c = 0; c < unloaded.size(); ++c) {
    EXPECT_EQ(unloaded[c], law_of(joints.crossings()[c]).at_zero_stress()) << c;
    EXPECT_EQ(joints.zero_stress_apertures()[c], law_of(joints.crossings()[c]).at_zero_stress()) << c;
  }

  // 3 kN on each 1 m face (the upper block of each face against its edge): σn = 3 MPa on both.
  std::vector<dda::ContactInfo> contacts;
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (std::size_t e = 0; e < m.network.edge_fractures[b].size(); ++e) {
      const int fracture = m.network.edge_fractures[b][e];
      const double y = fracture == 0 ? 0.3 : 0.7;
      if (fracture < 0 || !(geometry::centroid(blocks[b]).y < y)) continue;  // b below its face
      for (std::size_t o = 0; o < blocks.size(); ++o)
        if (o != b)
          for (std::size_t f = 0; f < m.network.edge_fractures[o].size(); ++f)
            if (m.network.edge_fractures[o][f] == fracture && geometry::centroid(blocks[o]).y > y)
              contacts.push_back({{static_cast<int>(b), 0, static_cast<int>(o), static_cast<int>(f)},
                                  dda::ContactState::locked, 0.0, 3.0e6});
    }
  ASSERT_EQ(contacts.size(), 2u);
  const std::vector<double> loaded = joints.apertures(blocks, contacts, 1e-9);
  for (std::size_t c = 0; c < loaded.size(); ++c)
    EXPECT_EQ(loaded[c], law_of(joints.crossings()[c]).closed(3.0e6)) << c;
  EXPECT_NE(joint.closed(3.0e6), fault.closed(3.0e6));

  // The top block lifted by 0.2 mm, the fault's contact carrying nothing: the fault opens,
  // a(0) + w by its law; the lower joint stays shut under its 3 MPa.
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (geometry::centroid(blocks[b]).y > 0.7)
      for (Point& p : blocks[b]) p.y += 2.0e-4;
  for (dda::ContactInfo& c : contacts)
    if (geometry::centroid(blocks[static_cast<std::size_t>(c.key.block_j)]).y > 0.7) c.normal_force = 0.0;
  const std::vector<double> lifted = joints.apertures(blocks, contacts, 1e-9);
  for (std::size_t c = 0; c < lifted.size(); ++c) {
    if (joints.crossings()[c].face.fracture == 1)
      EXPECT_NEAR(lifted[c], fault.open(2.0e-4), 1e-15) << c;
    else
      EXPECT_EQ(lifted[c], joint.closed(3.0e6)) << c;
  }
}

TEST(EmbeddedJoints, IsotropicTensorsSolveBitForBitAsScalars) {
  const Model m = make_model(9, 0.3, 0.7);
  std::vector<double> k(m.mesh.triangles.size());
  for (std::size_t t = 0; t < k.size(); ++t) k[t] = 1.0e-12 * (1.0 + 0.37 * std::sin(3.0 * t));
  std::vector<hydro::PermeabilityTensor> tensors;
  for (double v : k) tensors.push_back({v, 0.0, v});
  hydro::DarcySolver solver(m.mesh, {{}, {{"left", hydro::BoundaryKind::head, 1.0}, {"right", hydro::BoundaryKind::head, 0.0}}});
  const hydro::FlowSolution scalar = solver.solve(k);
  const hydro::FlowSolution tensor = solver.solve(tensors);
  EXPECT_EQ(scalar.head, tensor.head);
  EXPECT_EQ(scalar.boundary_flow("right"), tensor.boundary_flow("right"));
  for (const hydro::PermeabilityTensor& t : tensors) EXPECT_EQ(largest_principal_value(t), t.xx);
}

}  // namespace
}  // namespace hydrodda::coupling
