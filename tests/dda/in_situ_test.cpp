// Rollers and the in-situ stress: the kernels against hand values, and columns of blocks
// against the oedometer's exact solution and the equilibrium they must start in.

#include <gtest/gtest.h>

#include <cmath>

#include "dda/initial_stress.hpp"
#include "dda/selection.hpp"
#include "dda/system.hpp"
#include "geometry/block_network.hpp"
#include "geometry/joint_sets.hpp"
#include "geometry/tessellation.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_rectangle;

constexpr double kG = 9.81;
constexpr double kDensity = 2500.0;

TEST(InitialStress, FaceLoadsAreTheConsistentShareOfALinearTraction) {
  // σxx = −1e6 + 2e5 y on a vertical face x = 0 from y = 0 to 2, outward normal −x: the
  // traction σ n = (1e6 − 2e5 y, 0) runs 1e6 → 6e5. The ends take L (2 t1 + t2)/6 and
  // L (t1 + 2 t2)/6: 8.6667e5 and 7.3333e5 N; their sum is ∫ t ds = 1.6e6 N and their first
  // moment about y = 0, 2 × 7.3333e5, is ∫ y t ds = 1.4667e6 N m (exact to round-off).
  StressField field;
  field.at_reference = {-1e6, 0.0, 0.0};
  field.gradient = {2e5, 0.0, 0.0};
  const Point f0 = compute_face_load(field, {0, 0}, {0, 2}, {-1, 0});
  const Point f2 = compute_face_load(field, {0, 2}, {0, 0}, {-1, 0});
  EXPECT_NEAR(f0.x, 2.0 * (2 * 1e6 + 6e5) / 6, 1e-9);
  EXPECT_NEAR(f2.x, 2.0 * (1e6 + 2 * 6e5) / 6, 1e-9);
  EXPECT_NEAR(f0.x + f2.x, 1.6e6, 1e-9);
  EXPECT_NEAR(2.0 * f2.x, 2e6 - 2e5 * 8.0 / 3.0, 1e-9);
  EXPECT_EQ(f0.y, 0.0);
}

TEST(InitialStress, ContactPreloadResolvesTheTractionOnTheFace) {
  // Block i above block j, sharing the face y = 1 from x = 0 to 2; σyy = −3e5, τxy = 1e5.
  // Vertex (0, 1) of i on j's top edge carries half the face: normal 3e5 (compression),
  // and the shear on i along the edge (+x): the traction on i (normal −y) is
  // (−τxy, −σyy) = (−1e5, 3e5), so −1e5 × 1 m.
  StressField field;
  field.at_reference = {-1e5, -3e5, 1e5};
  const Polygon j = make_rectangle(0, 0, 2, 1);
  const Polygon i = make_rectangle(0, 1, 2, 2);
  const ContactPreload c = compute_contact_preload(field, i, 0, j, 2, 0.01);  // j's edge 2 runs (2,1)→(0,1)
  EXPECT_NEAR(c.normal, 3e5, 1e-9);
  EXPECT_NEAR(c.shear, 1e5, 1e-9);  // along j's edge direction (−x): −(−1e5)
}

// A column of n blocks 1 m wide and 1 m high on rollers: left, right and bottom.
ModelDefinition make_roller_column(int n, const std::optional<StressField>& stress) {
  ModelDefinition m;
  m.materials = {Material{kDensity, 1.0e10, 0.25}};
  for (int k = 0; k < n; ++k) m.blocks.push_back({make_rectangle(0, k, 1, k + 1), 0, false});
  const double h = n;
  for (auto [a, b] : {std::pair{Point{0, 0}, Point{0, h}}, std::pair{Point{1, 0}, Point{1, h}},
                      std::pair{Point{0, 0}, Point{1, 0}}}) {
    auto rollers = make_rollers_on_segment(m.blocks, a, b, 1e-9, stress);
    m.rollers.insert(m.rollers.end(), rollers.begin(), rollers.end());
  }
  m.initial_stress = stress;
  m.settings.analysis = Analysis::static_;
  m.settings.plane = Plane::strain;
  m.settings.time_step = 1e-2;
  return m;
}

// Ten blocks between side rollers on a roller base, under gravity, static, no initial stress:
// the oedometer. With εx = 0 (plane strain) a block's stress is σxx = ν/(1−ν) σyy, and
// in equilibrium its σyy is −ρ g (H − y_c): the virial of its two face forces ρ g (H − y_t)
// and ρ g (H − y_b) over its height. Its uniform strain εy = σyy / M, M = E(1−ν)/((1+ν)(1−2ν)),
// shortens it by h ρ g (H − y_c)/M, and the sum over the blocks (the midpoint rule, exact for a
// linear integrand) settles the top by ρ g H² / (2M), the continuous column's value: the
// discrete column has no other. 1% each, with a penetration tolerance of 1e-10 m (the
// default, 5e-6 m at this height, would let the nine contacts take 1% of the 0.1 mm).
TEST(Rollers, ColumnOnRollersIsAnOedometer) {
  const int n = 10;
  const double h = n, young = 1.0e10, nu = 0.25;
  ModelDefinition m = make_roller_column(n, std::nullopt);
  m.settings.penetration_tolerance = 1e-10;
  System system(std::move(m));
  system.run_to_equilibrium(2000);
  const double ratio = nu / (1 - nu);
  for (int k = 0; k < n; ++k) {
    const double expected = -kDensity * kG * (h - (k + 0.5));
    const auto s = system.stress(k);
    EXPECT_NEAR(s[1], expected, 0.01 * std::abs(expected)) << "block " << k;
    EXPECT_NEAR(s[0] / s[1], ratio, 0.01 * ratio) << "block " << k;
  }
  const double modulus = young * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double settlement = kDensity * kG * h * h / (2 * modulus);
  const double top = system.polygon(n - 1)[2].y - h;  // the top right corner
  EXPECT_NEAR(-top, settlement, 0.01 * settlement);
  EXPECT_NEAR(system.polygon(n - 1)[2].x, 1.0, 1e-9);  // the rollers hold the sides
}

// A 1 m block on a roller base, pushed along it by a horizontal force F at its centroid,
// dynamic: the rollers hold it up and do not resist the slide, x(t) = ½ (F/m) t² (1% at
// t = 0.2 s; 2500 kg, F = 5 kN: 2 cm), and it stays on the base (|y| under 1e-6 m).
TEST(Rollers, BlockSlidesFreelyAlongARollerBase) {
  ModelDefinition m;
  m.materials = {Material{kDensity, 1.0e10, 0.25}};
  m.blocks.push_back({make_rectangle(0, 0, 1, 1), 0, false});
  m.rollers = make_rollers_on_segment(m.blocks, {-5, 0}, {5, 0}, 1e-9, std::nullopt);
  ASSERT_EQ(m.rollers.size(), 2u);
  EXPECT_EQ(m.rollers[0].normal, (Point{0, -1}));
  m.point_loads.push_back({0, {0.5, 0.5}, constant_force({5000.0, 0.0})});
  m.settings.analysis = Analysis::dynamic;
  m.settings.time_step = 1e-3;
  System system(std::move(m));
  system.run_until(0.2);
  const double expected = 0.5 * 5000.0 / kDensity * 0.2 * 0.2;
  EXPECT_NEAR(system.displacement(0).x, expected, 0.01 * expected);
  EXPECT_LE(std::abs(system.displacement(0).y), 1e-6);
}

// The same column starting in its in-situ stress, σyy = −ρ g (H − y) and σxx = K0 σyy
// (K0 = 0.6, not the elastic 1/3: a stress the rollers hold, not one gravity makes here):
// each block starts with the stress at its centroid, its contacts and rollers with that
// stress's forces across its faces, so nothing moves: no block by more than 1e-6 of the
// column's height over 100 steps, and every stress stays where it started (1e-6 relative).
TEST(InitialStress, ColumnInItsInSituStressStartsInEquilibrium) {
  const int n = 10;
  const double h = n, k0 = 0.6;
  StressField field;
  field.reference_y = h;  // zero at the top
  field.gradient = {k0 * kDensity * kG, kDensity * kG, 0.0};
  System system(make_roller_column(n, field));
  for (int step = 0; step < 100; ++step) system.step();
  for (int k = 0; k < n; ++k) {
    EXPECT_LE(geometry::norm(system.displacement(k)), 1e-6 * h) << "block " << k;
    for (std::size_t v = 0; v < 4; ++v)
      EXPECT_LE(geometry::distance(system.polygon(k)[v], make_rectangle(0, k, 1, k + 1)[v]), 1e-6 * h);
    const auto start = field.at(k + 0.5);
    const auto s = system.stress(k);
    EXPECT_NEAR(s[0], start[0], 1e-6 * std::abs(start[1]));
    EXPECT_NEAR(s[1], start[1], 1e-6 * std::abs(start[1]));
  }
}

// The jointed models' in-situ field (σxx −10 MPa, σyy −20 MPa at the top, K0 = 0.5 down): the
// model of width × height on rollers left, right and bottom, its top under the field's σyy.
void place_in_jointed_models_field(ModelDefinition& m, double width, double height) {
  StressField field;
  field.at_reference = {-1.0e7, -2.0e7, 0.0};
  field.reference_y = height;
  field.gradient = {0.5 * kDensity * kG, kDensity * kG, 0.0};
  for (auto [a, b] : {std::pair{Point{0, 0}, Point{0, height}}, std::pair{Point{width, 0}, Point{width, height}},
                      std::pair{Point{0, 0}, Point{width, 0}}}) {
    auto rollers = make_rollers_on_segment(m.blocks, a, b, 1e-9, field);
    m.rollers.insert(m.rollers.end(), rollers.begin(), rollers.end());
  }
  m.tractions = make_tractions_on_segment(m.blocks, {0, height}, {width, height}, 1e-9, -2.0e7, -2.0e7, 0.0, 0.0);
  m.initial_stress = field;
  m.settings.time_step = 1e-2;
}

double largest_displacement(const System& system) {
  double largest = 0.0;
  for (int b = 0; b < system.block_count(); ++b) largest = std::max(largest, geometry::norm(system.displacement(b)));
  return largest;
}

// Blocks cut by two joint sets (inclined, non-persistent, spread) at 800 m depth under 20 MPa
// of overburden (a traction on the top), on rollers left, right and bottom, starting in the
// in-situ stress σyy = −20 MPa − ρ g (H − y), σxx = 10 MPa + K0 ρ g (H − y), K0 = 0.5, with
// joints of 40° friction (the inclined joints' shear stays under their strength): contacts
// along faces of every length and orientation, at T-junctions and corners, carry the stress
// from the first step. No block moves by more than 1e-8 of the model's height over 20 steps
// (measured 2.1e-9 m = 3.5e-10 H; not round-off because a contact's shear is held by moving
// its spring's reference point F/p along the edge, which moves where the force acts on the
// edge's block by that much: a moment error of F²/p, the penalty's own order). Without the
// contacts' shear the blocks move 6.2e-6 m, without any of their forces 8.5e-6 m.
TEST(InitialStress, JointedModelInItsInSituStressStartsInEquilibrium) {
  const double width = 10.0, height = 6.0;
  const geometry::Polygon domain = make_rectangle(0, 0, width, height);
  std::vector<geometry::FractureTrace> traces;
  for (int s = 0; s < 2; ++s) {
    geometry::JointSet set;
    set.angle = s == 0 ? 70.0 : 5.0;
    set.angle_spread = 5.0;
    set.spacing = s == 0 ? 1.5 : 1.0;
    set.spacing_spread = 0.2;
    set.length = s == 0 ? 4.0 : std::optional<double>{};
    set.region = domain;
    set.seed = 17 + s;
    for (const geometry::Segment2& t : geometry::generate_joint_traces(set)) traces.push_back({t, {}});
  }
  const geometry::BlockNetwork net = geometry::build_block_network({domain, traces, {}, 0.0, 0.0});
  ASSERT_GT(net.blocks.size(), 20u);
  ModelDefinition m;
  m.materials = {Material{kDensity, 1.0e10, 0.25}};
  m.joint = {40.0, 0.0, 0.0};
  for (const geometry::Polygon& p : net.blocks) m.blocks.push_back({p, 0, false});
  place_in_jointed_models_field(m, width, height);
  System system(std::move(m));
  for (int step = 0; step < 20; ++step) system.step();
  EXPECT_LE(largest_displacement(system), 1e-8 * height);
}

// A block of two bonded Voronoi sub-blocks (x 0–2 m) beside a plain block across a vertical
// joint (x = 2 m), 3 m high, on rollers left, right and bottom, under 20 MPa of overburden,
// starting in the in-situ stress of the jointed model above. The sub-blocks' bisector,
// y = 1.997 − x, crosses the base 3e-3 m from the block's corner (2, 0) on the joint, within
// the welding of 1e-2 size (geometry/tessellation.hpp): the corner stays where it is, so the
// sub-block's face along the joint touches the plain block all along and its contacts carry
// the field's force from the first step. Nothing moves by more than 1e-8 of the height in the
// first step (the F²/p of the contacts' shear, as above; measured 2.6e-9 m = 8.5e-10 H).
// Welded onto the crossing, the corner stood 3e-3 m off the joint at the base, the face's
// lower end carried nothing, and the first step moved the blocks by 1.5e-5 m.
TEST(InitialStress, TessellatedBlockBesideAJointStartsInEquilibrium) {
  const double width = 4.0, height = 3.0, size = 1.0;
  const Point middle{0.9985, 0.9985};  // on the bisector
  const Point across{0.3, 0.3};        // along its normal
  const geometry::Tessellation parts = geometry::tessellate(
      make_rectangle(0, 0, 2, height), std::vector<Point>{middle - across, middle + across}, size,
      geometry::TessellationKind::voronoi);
  ASSERT_EQ(parts.cells.size(), 2u);
  ModelDefinition m;
  m.materials = {Material{kDensity, 1.0e10, 0.25}};
  m.joint = {40.0, 0.0, 0.0};
  m.joint_types = {Joint{40.0, 1.0e9, 1.0e9}};  // the bond's, strong enough never to break
  for (std::size_t c = 0; c < parts.cells.size(); ++c) {
    BlockDefinition sub{parts.cells[c], 0, false};
    for (int source : parts.edge_sources[c]) {
      sub.edge_bonds.push_back(source >= 0 ? 0 : -1);
      sub.edge_joints.push_back(source >= 0 ? 1 : 0);
    }
    m.blocks.push_back(std::move(sub));
  }
  BlockDefinition plain{make_rectangle(2, 0, width, height), 0, false};
  plain.edge_bonds.assign(4, -1);  // as a scenario's untessellated blocks have
  m.blocks.push_back(std::move(plain));
  place_in_jointed_models_field(m, width, height);
  System system(std::move(m));
  system.step();
  EXPECT_LE(largest_displacement(system), 1e-8 * height);
}

}  // namespace
}  // namespace hydrodda::dda
