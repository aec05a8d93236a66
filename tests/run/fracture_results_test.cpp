// Results per fracture against the exact opening of two blocks moved by hand: a 2 m × 1 m
// domain cut by one vertical fracture at x = 1 m (aperture a0 between the blocks), the right
// block moved by an affine map, the left one left in place. The opening along the face is
// then a0 + u_x(right block at the face), exactly, and the meter's mean, largest value and open
// length are exact for an opening linear along the face (tolerances: round-off, 1e-15 m).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "fractures/fracture_results.hpp"
#include "geometry/block_network.hpp"
#include "mesh/triangle_mesh.hpp"
#include "run/scenario_fractures.hpp"

namespace geometry = hydrodda::geometry;
namespace fractures = hydrodda::fractures;
namespace run = hydrodda::run;
using geometry::Point;

namespace {

constexpr double kAperture = 1e-3;

fractures::FractureMeter two_block_meter() {
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  request.traces = {{{{1, 0}, {1, 1}}, {geometry::TraceSource::joint_set, 1, 3}}};
  request.aperture = kAperture;
  fractures::FractureLayout layout{request.traces, geometry::build_block_network(request)};
  return fractures::FractureMeter(std::move(layout), 0.1);
}

// The network's blocks with the right one (centroid x > 1) mapped by `move`.
std::vector<geometry::Polygon> moved(const fractures::FractureMeter& meter, const std::function<Point(Point)>& move) {
  std::vector<geometry::Polygon> blocks = meter.layout().network.blocks;
  for (geometry::Polygon& b : blocks)
    if (geometry::centroid(b).x > 1.0)
      for (Point& p : b) p = move(p);
  return blocks;
}

TEST(FractureResults, TranslatedBlockOpensAndSlidesByItsDisplacement) {
  const fractures::FractureMeter meter = two_block_meter();
  ASSERT_EQ(meter.layout().network.blocks.size(), 2u);
  const double d = 2e-4, s = -3e-4;  // opening and sliding
  const auto blocks = moved(meter, [&](Point p) { return p + Point{d, s}; });
  const fractures::FractureState state = meter.measure(blocks, 0.0);
  ASSERT_EQ(state.fractures.size(), 1u);
  const fractures::FractureResult& r = state.fractures[0];
  EXPECT_EQ(r.id, 0);
  EXPECT_EQ(r.origin.source, geometry::TraceSource::joint_set);
  EXPECT_EQ(r.origin.set, 1);
  EXPECT_NEAR(r.length, 1.0, 1e-15);
  EXPECT_NEAR(r.open_length, 1.0, 1e-15);
  EXPECT_NEAR(r.mean_aperture, kAperture + d, 1e-15);
  EXPECT_NEAR(r.max_aperture, kAperture + d, 1e-15);
  EXPECT_NEAR(r.max_shear, std::abs(s), 1e-15);
  // Pieces at most 0.1 m long along the whole face, all open.
  EXPECT_EQ(state.pieces.size(), 10u);
  for (const fractures::FracturePiece& p : state.pieces) {
    EXPECT_TRUE(p.open);
    EXPECT_NEAR(p.aperture, kAperture + d, 1e-15);
  }
}

// u_x = β y on the right block: the gap a0 + β y closes at y* = −a0/β = 0.5 m, so
// open length = 0.5 m, mean aperture = ∫₀^½ (a0 + β y) dy / 1 m = a0/4, largest = a0. The
// right block's edge turns by θ = atan β, and the opening is taken along the two edges' mean
// normal: it is the gap × cos(θ/2) (5e-10 m less than the gap; round-off), and the shear the
// displacement βy × sin(θ/2), at most |β| θ/2 = 2e-6 m. The open length is exact: the gap
// vanishes at y*.
TEST(FractureResults, TiltedBlockClosesHalfTheFaceExactly) {
  const fractures::FractureMeter meter = two_block_meter();
  const double beta = -2.0 * kAperture;
  const auto blocks = moved(meter, [&](Point p) { return p + Point{beta * p.y, 0.0}; });
  const fractures::FractureState state = meter.measure(blocks, 0.0);
  ASSERT_EQ(state.fractures.size(), 1u);
  const fractures::FractureResult& r = state.fractures[0];
  const double theta = std::atan(std::abs(beta));
  EXPECT_NEAR(r.open_length, 0.5, 1e-12);
  EXPECT_NEAR(r.mean_aperture, kAperture / 4.0 * std::cos(theta / 2.0), 1e-15);
  EXPECT_NEAR(r.max_aperture, kAperture * std::cos(theta / 2.0), 1e-15);
  EXPECT_LE(r.max_shear, std::abs(beta) * std::sin(theta / 2.0) + 1e-15);
  // A wedge closing at y*: the opening grows at |β| cos(θ/2) from there (round-off, 1e-12
  // relative: the slope of a difference over 0.1 m).
  EXPECT_NEAR(r.tip_opening_angle, std::abs(beta) * std::cos(theta / 2.0), 1e-12 * std::abs(beta));
  EXPECT_NEAR(r.tip.y, 0.5, 1e-9);
  // The pieces are cut where the face closes: every piece is wholly open (below y*) or closed.
  double open = 0.0, closed = 0.0;
  for (const fractures::FracturePiece& p : state.pieces) {
    const double length = geometry::distance(p.segment[0], p.segment[1]);
    const double top = std::max(p.segment[0].y, p.segment[1].y), bottom = std::min(p.segment[0].y, p.segment[1].y);
    if (p.open) {
      open += length;
      EXPECT_LE(top, 0.5 + 1e-12);
    } else {
      closed += length;
      EXPECT_GE(bottom, 0.5 - 1e-12);
    }
  }
  // Drawn on the midline, which leans by β/2: lengths grow by √(1 + β²/4) − 1 ≈ 5e-7.
  EXPECT_NEAR(open, 0.5, 1e-6);
  EXPECT_NEAR(closed, 0.5, 1e-6);
}

// open_share = open_length / length, and `open` over at least kOpenShare = 0.9 of it: u_x = β y
// on the right block closes the face above y* = −a0/β, so open_share = y* / 1 m. β = −4 a0:
// share 0.25, a closed fracture with an open wedge at its foot; β = −2 a0 (the tilted block of
// the test above): half open, as a flexed layer's joints are, closed; β = −a0/0.95: share 0.95,
// open. Tolerance: round-off of the cut at y* (1e-12).
TEST(FractureResults, AFractureIsOpenOverNineTenthsOfItsLength) {
  const fractures::FractureMeter meter = two_block_meter();
  for (const double share : {0.25, 0.5, 0.75, 0.95}) {
    const double beta = -kAperture / share;
    const auto blocks = moved(meter, [&](Point p) { return p + Point{beta * p.y, 0.0}; });
    const fractures::FractureState state = meter.measure(blocks, 0.0);
    ASSERT_EQ(state.fractures.size(), 1u);
    const fractures::FractureResult& r = state.fractures[0];
    EXPECT_NEAR(r.open_length, share, 1e-12) << share;
    EXPECT_NEAR(r.open_share, share, 1e-12) << share;
    EXPECT_EQ(r.open, share >= fractures::kOpenShare) << share;
  }
  // Wholly closed and wholly open.
  const fractures::FractureState closed = meter.measure(moved(meter, [](Point p) { return p + Point{-kAperture, 0.0}; }), 0.0);
  EXPECT_EQ(closed.fractures[0].open_share, 0.0);
  EXPECT_FALSE(closed.fractures[0].open);
  const fractures::FractureState open = meter.measure(moved(meter, [](Point p) { return p + Point{kAperture, 0.0}; }), 0.0);
  EXPECT_EQ(open.fractures[0].open_share, 1.0);
  EXPECT_TRUE(open.fractures[0].open);
}

// Each fracture's pieces take its own joint type's law: a 3 m × 1 m domain cut at x = 1 m (the
// default type) and x = 2 m (type 1), aperture a0; the middle block moved left by a0 shuts the
// first (unloaded: a(0) = a_r + V_m of the default law) and opens the second to 2 a0 (a(0) + 2 a0
// of type 1's). Exact: the laws' own values (round-off of the gauge, 1e-15 m).
TEST(FractureResults, EachFractureTakesItsJointTypesApertureLaw) {
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {3, 0}, {3, 1}, {0, 1}};
  request.traces = {{{{1, 0}, {1, 1}}, {geometry::TraceSource::listed, 0, 0}, 0},
                    {{{2, 0}, {2, 1}}, {geometry::TraceSource::listed, 0, 1}, 1}};
  request.aperture = kAperture;
  fractures::FractureLayout layout{request.traces, geometry::build_block_network(request)};
  ASSERT_EQ(layout.network.blocks.size(), 3u);
  const fractures::FractureMeter meter(std::move(layout), 0.1);
  std::vector<geometry::Polygon> blocks = meter.layout().network.blocks;
  for (geometry::Polygon& b : blocks)
    if (const double x = geometry::centroid(b).x; x > 1.0 && x < 2.0)
      for (Point& p : b) p.x -= kAperture;
  const hydrodda::hydro::JointApertureLaw joint{1.0e-5, 2.0e11, 1.0e-4}, fault{2.0e-4, 5.0e10, 3.0e-4};
  const hydrodda::coupling::JointApertureLaws laws({joint, fault}, {0, 1});
  const fractures::FractureState state = meter.measure(blocks, 1e-9, {}, laws);
  ASSERT_EQ(state.fractures.size(), 2u);
  EXPECT_FALSE(state.fractures[0].open);
  EXPECT_TRUE(state.fractures[1].open);
  EXPECT_NEAR(state.fractures[0].hydraulic_aperture, joint.at_zero_stress(), 1e-15);
  EXPECT_NEAR(state.fractures[1].hydraulic_aperture, fault.open(2.0 * kAperture), 1e-15);
  for (const fractures::FracturePiece& piece : state.pieces)
    EXPECT_NEAR(piece.hydraulic_aperture, piece.fracture == 0 ? joint.at_zero_stress() : fault.open(2.0 * kAperture), 1e-15);
  // One law for both (the former rule): the fault reads the default law.
  const fractures::FractureState one = meter.measure(blocks, 1e-9, {}, joint);
  EXPECT_NEAR(one.fractures[1].hydraulic_aperture, joint.open(2.0 * kAperture), 1e-15);
}

// The contacts on the face, keyed as the DDA keys them: vertex 0 of the block across against
// each edge of `block` that lies on fracture 0, with the given normal forces.
std::vector<hydrodda::dda::ContactInfo> contacts_on_face(const fractures::FractureMeter& meter,
                                                         const std::vector<double>& forces) {
  const geometry::BlockNetwork& network = meter.layout().network;
  std::vector<hydrodda::dda::ContactInfo> contacts;
  for (int block = 0; block < 2; ++block)
    for (std::size_t edge = 0; edge < network.edge_fractures[block].size(); ++edge)
      if (network.edge_fractures[block][edge] == 0 && contacts.empty())
        for (double force : forces) {
          hydrodda::dda::ContactInfo c;
          c.key = {1 - block, static_cast<int>(contacts.size()), block, static_cast<int>(edge)};
          c.state = force > 0.0 ? hydrodda::dda::ContactState::locked : hydrodda::dda::ContactState::open;
          c.normal_force = force;
          contacts.push_back(c);
        }
  return contacts;
}

// normal_stress = Σ F_n / L over the whole 1 m face (an exact identity of the definition): two
// contacts pressing with 3 MN/m and 1 MN/m, and an open one, give 4 MPa whether the face is
// closed all along or only over its upper 0.75 m (β = −4 a0 above: the force over the closed
// part alone would be 5.33 MPa); the open contact's force is none. Tolerance: round-off.
TEST(FractureResults, NormalStressIsTheContactForcesOverTheWholeLength) {
  const fractures::FractureMeter meter = two_block_meter();
  const auto contacts = contacts_on_face(meter, {3e6, 1e6, 0.0});
  ASSERT_EQ(contacts.size(), 3u);
  const auto closed = moved(meter, [](Point p) { return p + Point{-kAperture, 0.0}; });
  const auto wedge = moved(meter, [](Point p) { return p + Point{-4.0 * kAperture * p.y, 0.0}; });
  for (const auto& blocks : {closed, wedge}) {
    const fractures::FractureState state = meter.measure(blocks, 0.0, contacts);
    ASSERT_EQ(state.fractures.size(), 1u);
    EXPECT_NEAR(state.fractures[0].normal_stress, 4e6, 1e-9);
  }
  // Nothing presses on it: none.
  EXPECT_EQ(meter.measure(closed, 0.0).fractures[0].normal_stress, 0.0);
}

// A 2 m × 2 m domain cut by a vertical fracture (x = 1 m) and a horizontal one (y = 1 m), both
// of aperture a0: the vertical fracture has a lower and an upper face, meeting at the junction.
// The lower right block moves right by d: the lower face opens to a0 + d. The upper right block
// moves by u_x = −a0 − ε + γ (y − 1): the upper face overlaps by ε at the junction and opens
// as a wedge from y* = 1 + ε/γ, at γ cos(θ/2) (θ = atan γ, the frame of the two edges). Each
// face's gauge at the junction reads its own blocks: every piece of the lower face is open by
// a0 + d (its edges stay parallel, so exactly), the upper face is closed below y*, and the
// wedge's tip is found there (round-off). Read across the junction, the upper face's first
// node took the lower blocks' a0 + d, its first piece opened from the junction, and the tip was
// lost.
TEST(FractureResults, EachFaceIsReadOnItsOwnBlocksAtAJunction) {
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const geometry::TraceOrigin listed{geometry::TraceSource::listed, 0, 0};
  request.traces = {{{{1, 0}, {1, 2}}, listed}, {{{0, 1}, {2, 1}}, {geometry::TraceSource::listed, 0, 1}}};
  request.aperture = kAperture;
  fractures::FractureLayout layout{request.traces, geometry::build_block_network(request)};
  ASSERT_EQ(layout.network.blocks.size(), 4u);
  const fractures::FractureMeter meter(std::move(layout), 0.1);
  const double d = 5e-4, epsilon = 1e-5, gamma = 2e-3;
  std::vector<geometry::Polygon> blocks = meter.layout().network.blocks;
  for (geometry::Polygon& b : blocks) {
    const Point c = geometry::centroid(b);
    if (c.x < 1.0) continue;
    for (Point& p : b) p = c.y < 1.0 ? p + Point{d, 0.0} : p + Point{-kAperture - epsilon + gamma * (p.y - 1.0), 0.0};
  }
  const fractures::FractureState state = meter.measure(blocks, 0.0);
  const fractures::FractureResult* vertical = nullptr;
  for (const fractures::FractureResult& r : state.fractures)
    if (r.id == 0) vertical = &r;
  ASSERT_NE(vertical, nullptr);
  const double theta = std::atan(gamma), tip_y = 1.0 + epsilon / gamma;
  EXPECT_NEAR(vertical->tip_opening_angle, gamma * std::cos(theta / 2.0), 1e-12 * gamma);
  EXPECT_NEAR(vertical->tip.y, tip_y, 1e-9);
  int lower = 0, upper = 0;
  for (const fractures::FracturePiece& p : state.pieces) {
    if (p.fracture != 0) continue;
    const double bottom = std::min(p.segment[0].y, p.segment[1].y), top = std::max(p.segment[0].y, p.segment[1].y);
    if (top <= 1.0 + 1e-6) {
      ++lower;
      EXPECT_TRUE(p.open);
      EXPECT_NEAR(p.aperture, kAperture + d, 1e-15) << "lower piece from y = " << bottom;
    } else {
      ++upper;
      EXPECT_EQ(p.open, bottom >= tip_y - 1e-9) << "upper piece from y = " << bottom;
    }
  }
  EXPECT_EQ(lower, 10);
  EXPECT_GE(upper, 10);
}

TEST(FractureResults, BlocksThatDoNotFitTheNetworkAreRefused) {
  const fractures::FractureMeter meter = two_block_meter();
  std::vector<geometry::Polygon> blocks = meter.layout().network.blocks;
  blocks.pop_back();
  EXPECT_THROW(meter.measure(blocks, 0.0), std::invalid_argument);
}

// The flow zones (FractureMeter::flow_zones, through a spatial grid) against the loop over every
// face that defines them: each element's centroid goes to the nearest face it projects onto, the
// lower face index on a tie. A 10 m × 4 m domain cut by tilted joints, beds and two long oblique
// traces, over a structured mesh of 32,000 triangles: the same zone for every element.
TEST(FractureResults, FlowZonesAreTheNearestProjectingFace) {
  geometry::BlockNetworkRequest request;
  request.domain = {{0, 0}, {10, 0}, {10, 4}, {0, 4}};
  const geometry::TraceOrigin joint{geometry::TraceSource::joint_set, 1, 0};
  for (int i = 1; i < 10; ++i) request.traces.push_back({{{i + 0.03 * (i % 3), 0}, {i - 0.02 * (i % 2), 4}}, joint});
  for (int j = 1; j < 4; ++j) request.traces.push_back({{{0, j + 0.01 * j}, {10, j - 0.02}}, joint});
  request.traces.push_back({{{0.2, 0}, {9.7, 4}}, joint});
  request.traces.push_back({{{0, 3.6}, {7.3, 0}}, joint});
  request.aperture = 1e-3;
  fractures::FractureLayout layout{request.traces, geometry::build_block_network(request)};
  const std::vector<geometry::FractureFace> faces = layout.network.faces;
  const fractures::FractureMeter meter(std::move(layout), 0.1);

  hydrodda::mesh::TriangleMesh mesh;
  constexpr int nx = 200, ny = 80;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.nodes.push_back({10.0 * i / nx, 4.0 * j / ny});
  const auto node = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      mesh.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  const fractures::FractureMeter::FlowZones zones = meter.flow_zones(mesh);
  ASSERT_EQ(zones.fracture.size(), mesh.triangles.size());
  int in_a_zone = 0;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const Point c = hydrodda::mesh::triangle_centroid(mesh, t);
    int nearest = -1;
    double nearest_distance = INFINITY;
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const Point d = faces[k].segment.to - faces[k].segment.from;
      const double length2 = geometry::dot(d, d);
      const double along = geometry::dot(c - faces[k].segment.from, d);
      if (!(length2 > 0.0) || along < 0.0 || along > length2) continue;
      const double distance = std::abs(geometry::dot(c - faces[k].segment.from, Point{-d.y, d.x})) / std::sqrt(length2);
      if (distance < nearest_distance) {
        nearest_distance = distance;
        nearest = static_cast<int>(k);
      }
    }
    const int expected = nearest >= 0 ? faces[nearest].fracture : -1;
    ASSERT_EQ(zones.fracture[t], expected) << "triangle " << t << " at (" << c.x << ", " << c.y << ")";
    in_a_zone += expected >= 0;
  }
  EXPECT_GT(in_a_zone, mesh.triangle_count() * 9 / 10);
}

// A square of side h centred on c, cut into two triangles: each one's longest edge is h √2.
hydrodda::mesh::TriangleMesh square_mesh(Point c, double h) {
  hydrodda::mesh::TriangleMesh mesh;
  mesh.nodes = {{c.x - h / 2, c.y - h / 2}, {c.x + h / 2, c.y - h / 2}, {c.x + h / 2, c.y + h / 2}, {c.x - h / 2, c.y + h / 2}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

// The tips a mesh does not resolve: s* = sqrt(12 k_m / α³) (1.22 mm for α = 2e-3 and k_m =
// 1e-15 m²) against the longest edge of the element holding the tip, with the advice that
// fits where the tip lies: on its trace a smaller mesh.fracture_size; carried off it, a mesh
// refined around the tip; in a mesh file, a refinement of the file.
TEST(FractureResults, AWedgeTipTheMeshDoesNotResolveIsNamed) {
  fractures::FractureState state;
  fractures::FractureResult sharp, blunt, none;
  sharp.id = 3;
  sharp.tip_opening_angle = 2e-3;
  sharp.tip = {1.5, 0.25};
  blunt.id = 5;
  blunt.tip_opening_angle = 5e-4;
  blunt.tip = {1.5, 0.25};
  none.id = 7;
  state.fractures = {none, blunt, sharp};
  const double k_m = 1e-15, s_star = std::sqrt(12.0 * k_m / 8e-9);
  std::vector<geometry::FractureTrace> traces(8);
  traces[3].segment = {{1.5, 0.0}, {1.5, 1.0}};     // the tip on its trace
  traces[5].segment = {{1.498, 0.0}, {1.498, 1.0}};  // 2 mm from it
  const hydrodda::hydro::JointApertureLaw bare;
  hydrodda::scenario::MeshDefinition settings;
  settings.size = 0.15;
  settings.fracture_size = 1e-4;
  settings.refine_distance = 0.2;

  // Elements of 2 mm across: the sharp tip (s* = 1.22 mm) is the least resolved.
  const hydrodda::mesh::TriangleMesh coarse = square_mesh(sharp.tip, 2e-3 / std::sqrt(2.0));
  const hydrodda::mesh::PointLocator coarse_locator(coarse);
  const auto elements = fractures::find_wedge_tip_elements(state, k_m, bare, coarse, coarse_locator, traces);
  ASSERT_EQ(elements.size(), 2u);
  const fractures::WedgeTipElement* least = &elements.front();
  EXPECT_EQ(least->tip.fracture, 3);
  EXPECT_EQ(elements.back().tip.fracture, 5);  // s* = 9.8 mm: resolved
  EXPECT_NEAR(least->element_size, 2e-3, 1e-15);
  EXPECT_NEAR(least->tip.length, s_star, 1e-15);
  EXPECT_EQ(least->trace_distance, 0.0);
  const auto message = run::describe_unresolved_wedge_tips(elements, settings);
  ASSERT_TRUE(message.has_value());
  EXPECT_NE(message->find("fracture 3 opens as a wedge from (1.5, 0.25) at an angle of 0.002"), std::string::npos)
      << *message;
  EXPECT_NE(message->find("s* = sqrt(12 k_m / angle^3) = 0.00122 m, and the fluid element there is 0.002 m across"),
            std::string::npos) << *message;
  EXPECT_NE(message->find("give mesh.fracture_size = 0.00031 m (s*/4), or refine around the tip (size s*/4): "
                          "[[mesh.refine]] point = [1.5, 0.25], size = 0.00031"),
            std::string::npos) << *message;

  // Carried 2 mm off its trace (the blunt tip, s* = 9.8 mm, in elements of 14 mm): a finer
  // fracture_size would refine the trace, not the tip.
  const hydrodda::mesh::TriangleMesh wide = square_mesh(sharp.tip, 14e-3 / std::sqrt(2.0));
  const hydrodda::mesh::PointLocator wide_locator(wide);
  fractures::FractureState blunt_only;
  blunt_only.fractures = {blunt};
  const auto carried =
      fractures::find_wedge_tip_element(*fractures::find_sharpest_wedge_tip(blunt_only, k_m, bare), wide, wide_locator, traces);
  ASSERT_TRUE(carried.has_value());
  EXPECT_NEAR(carried->trace_distance, 2e-3, 1e-12);
  const auto off_trace = run::describe_unresolved_wedge_tips({&*carried, 1}, settings);
  ASSERT_TRUE(off_trace.has_value());
  EXPECT_NE(off_trace->find("carried the tip 0.002 m from the fracture's trace"), std::string::npos) << *off_trace;
  EXPECT_NE(off_trace->find("so a smaller one does not reach it: refine around the tip (size s*/4): [[mesh.refine]] "
                            "point = [1.5, 0.25], size = 0.0024"),
            std::string::npos) << *off_trace;
  EXPECT_EQ(off_trace->find("give mesh.fracture_size"), std::string::npos) << *off_trace;
  hydrodda::scenario::MeshDefinition from_file = settings;
  from_file.file = "seal.msh";
  EXPECT_NE(run::describe_unresolved_wedge_tips({&*carried, 1}, from_file)->find("refine the mesh file to"),
            std::string::npos);
  // Two unresolved tips: a table for each.
  const std::vector<fractures::WedgeTipElement> both = fractures::find_wedge_tip_elements(state, k_m, bare, wide, wide_locator, traces);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_NE(run::describe_unresolved_wedge_tips(both, settings)->find("refine around the 2 unresolved tips"),
            std::string::npos);

  // Elements under s*/2 resolve the tip; a tip outside the mesh is not judged.
  const hydrodda::mesh::TriangleMesh fine = square_mesh(sharp.tip, 0.5e-3 / std::sqrt(2.0));
  const hydrodda::mesh::PointLocator fine_locator(fine);
  const auto resolved = fractures::find_wedge_tip_elements(state, k_m, bare, fine, fine_locator, traces);
  ASSERT_EQ(resolved.size(), 2u);
  EXPECT_FALSE(run::describe_unresolved_wedge_tips(resolved, settings).has_value());
  const hydrodda::mesh::TriangleMesh elsewhere = square_mesh({5.0, 5.0}, 1.0);
  const hydrodda::mesh::PointLocator elsewhere_locator(elsewhere);
  EXPECT_TRUE(fractures::find_wedge_tip_elements(state, k_m, bare, elsewhere, elsewhere_locator, traces).empty());

  // A joint whose aperture at zero opening is the wedge's at s* has no sharp tip.
  hydrodda::hydro::JointApertureLaw residual;
  residual.residual_aperture = 3e-6;
  const auto residual_elements = fractures::find_wedge_tip_elements(state, k_m, residual, coarse, coarse_locator, traces);
  ASSERT_EQ(residual_elements.size(), 1u);
  EXPECT_EQ(residual_elements.front().tip.fracture, 5);
  // The tip itself (summary.json's tip_length): the sharpest, or none without a sharp one.
  const auto tip = fractures::find_sharpest_wedge_tip(state, k_m, bare);
  ASSERT_TRUE(tip.has_value());
  EXPECT_EQ(tip->fracture, 3);
  EXPECT_NEAR(tip->length, s_star, 1e-15);
  EXPECT_EQ(tip->point.y, 0.25);
  EXPECT_EQ(fractures::find_sharpest_wedge_tip(state, k_m, residual)->fracture, 5);
  fractures::FractureState without_tips;
  without_tips.fractures = {none};
  EXPECT_FALSE(fractures::find_sharpest_wedge_tip(without_tips, k_m, bare).has_value());
}

}  // namespace

