// Corners at a node of intact rock (System::drop_corner_contacts_within_intact_rock): where six
// bonded triangles meet at a point, each one's corner there lies on the ends of the others'
// faces. A corner whose two faces are intact bonds reaches a third sub-block only through its
// bonded neighbours, so where both corners are inside intact rock neither touches the other's
// faces' ends; so too where a corner has one face on the rock's edge (a joint through the node,
// no bond) and the other bonded. Once a face at either corner is broken, the contacts with the
// broken faces come back; at a crack's tip, those with the ends of intact faces past the
// corner's neighbours, which it reaches about the node through them, do not, while along a
// crack through the node the corners across it touch the far side's faces.
// Exact: the contacts are counted, no tolerance.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "dda/system.hpp"
#include "geometry/polygon.hpp"

namespace hydrodda::dda {
namespace {

constexpr int kTriangles = 6;

// Six triangles around a centre off the ring's middle (unequal angles at it, as a
// tessellation's): triangle i = (centre, ring i, ring i+1), edges 0 and 2 its spokes i and
// i+1 (bond i and i+1 mod 6), edge 1 the ring; every spoke bonded, the ring free.
ModelDefinition make_node(const std::vector<int>& broken) {
  const Point centre{0.07, -0.04};
  std::array<Point, kTriangles> ring;
  for (int i = 0; i < kTriangles; ++i) {
    const double angle = 2.0 * M_PI * i / kTriangles + 0.15 * std::sin(3.0 * i);
    ring[static_cast<std::size_t>(i)] = {std::cos(angle), std::sin(angle)};
  }
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  for (int i = 0; i < kTriangles; ++i) {
    BlockDefinition b{{centre, ring[static_cast<std::size_t>(i)], ring[static_cast<std::size_t>((i + 1) % kTriangles)]}, 0, false};
    b.edge_joints = {1, 0, 1};
    b.edge_bonds = {i, -1, (i + 1) % kTriangles};
    m.blocks.push_back(b);
  }
  m.joint = {30.0, 0.0, 0.0};
  m.joint_types = {Joint{25.0, 6.0e6, 2.0e6}};
  m.settings.analysis = Analysis::static_;
  m.settings.gravity = {0.0, 0.0};
  m.settings.time_step = 1e-3;
  m.broken_bonds = broken;
  return m;
}

// Contacts of a triangle's centre corner (vertex 0) with a triangle that is not its neighbour
// across a spoke (tip to tip at the node).
int count_tip_to_tip(const System& system) {
  int count = 0;
  for (const ContactInfo& c : system.contacts()) {
    const int apart = (c.key.block_j - c.key.block_i + kTriangles) % kTriangles;
    if (c.key.vertex == 0 && apart != 1 && apart != kTriangles - 1) ++count;
  }
  return count;
}

TEST(NodeCornerContacts, ACornerOfIntactRockHasNoContactWithTheThirdSubBlocksAtItsNode) {
  System system(make_node({}));
  system.step();
  EXPECT_EQ(count_tip_to_tip(system), 0);
  // The spokes' own end contacts are there: two a spoke (one at each end), six spokes.
  int face_contacts = 0;
  for (const ContactInfo& c : system.contacts()) face_contacts += system.bond_of_contact(c.key) >= 0 ? 1 : 0;
  EXPECT_GE(face_contacts, 2 * kTriangles);
}

TEST(NodeCornerContacts, ACornerOnTheRocksEdgeHasNoContactWithTheThirdSubBlocksAtItsNode) {
  // Spoke 0 a joint, not a bond: the node lies on the edge of the tessellated rock (as where a
  // bedding joint bounds it), triangles 0 and 5 each with one face on the joint. The old rule,
  // both faces intact bonds, gave their corners the contacts a broken face gives (the test
  // below); their bonded neighbours close them as they close the others. The rule is about
  // bonded faces' ends: a corner at the joint face's end is a joint's contact, left as it is.
  ModelDefinition m = make_node({});
  for (BlockDefinition& b : m.blocks)
    for (int& bond : b.edge_bonds) bond = bond == 0 ? -1 : (bond > 0 ? bond - 1 : bond);
  m.blocks.front().edge_joints[0] = 0;
  m.blocks.back().edge_joints[2] = 0;
  System system(m);
  system.step();
  int at_bonded_face_ends = 0;
  for (const ContactInfo& c : system.contacts()) {
    const int apart = (c.key.block_j - c.key.block_i + kTriangles) % kTriangles;
    if (c.key.vertex == 0 && apart != 1 && apart != kTriangles - 1 && system.bond_of_contact(c.key) >= 0)
      ++at_bonded_face_ends;
  }
  EXPECT_EQ(at_bonded_face_ends, 0);
}

TEST(NodeCornerContacts, ABrokenFaceAtTheCornerGivesItsTipToTipContactsBack) {
  // Spoke 0 broken: triangles 0 and 5 have a broken face at the centre, so the others'
  // corners there touch it again; those of triangles 1-4, all faces intact, still touch none
  // of each other's.
  System system(make_node({0}));
  system.step();
  int with_a_broken_corner = 0, between_intact_corners = 0;
  const auto broken_corner = [](int block) { return block == 0 || block == kTriangles - 1; };
  for (const ContactInfo& c : system.contacts()) {
    const int apart = (c.key.block_j - c.key.block_i + kTriangles) % kTriangles;
    if (c.key.vertex != 0 || apart == 1 || apart == kTriangles - 1) continue;
    ((broken_corner(c.key.block_i) || broken_corner(c.key.block_j)) ? with_a_broken_corner : between_intact_corners) += 1;
  }
  EXPECT_GT(with_a_broken_corner, 0);
  EXPECT_EQ(between_intact_corners, 0);
}

// Whether spoke `bond` (between triangles bond − 1 and bond) is a face of neither of the
// neighbours of triangle `block` about the node (block ± 1) nor of the triangle itself.
bool past_the_neighbours(int block, int bond) {
  const auto near = [block](int t) { return (t - block + kTriangles + 1) % kTriangles <= 2; };
  return !near((bond + kTriangles - 1) % kTriangles) && !near(bond);
}

// At a crack's tip (spoke 0 broken: triangles 0 and 5 beside the crack), a corner beside it
// reaches the faces past its neighbours about the node through those neighbours, which stand
// between: no contact with those faces' ends, only with the broken face and its neighbours'
// faces. (At the resolved seal's new breaks, (5.77, 5.25) at 1,200 m over hydrostatic, such a
// corner sat 8e-7 m into the end of an intact face two sub-blocks away across the node: the
// contact forces never settled and the step was cut to nothing.)
TEST(NodeCornerContacts, AtACracksTipTheCornersBesideItDoNotTouchTheIntactFacesPastTheirNeighbours) {
  System system(make_node({0}));
  system.step();
  int past_neighbours = 0, on_broken_faces = 0;
  for (const ContactInfo& c : system.contacts()) {
    const int apart = (c.key.block_j - c.key.block_i + kTriangles) % kTriangles;
    if (c.key.vertex != 0 || apart == 1 || apart == kTriangles - 1) continue;
    const int bond = system.bond_of_contact(c.key);
    ASSERT_GE(bond, 0) << "a corner at the node against a spoke";
    if (system.is_bond_broken(bond))
      ++on_broken_faces;
    else if (past_the_neighbours(c.key.block_i, bond))
      ++past_neighbours;
  }
  EXPECT_EQ(past_neighbours, 0);
  EXPECT_GT(on_broken_faces, 0);
}

// A crack through the node (spokes 0 and 3 broken): triangles 0-2 on one side, 3-5 on the
// other. A corner reaches only its own side through intact faces; across the crack the corners
// face the far side's faces, intact ones included, as a joint's do.
TEST(NodeCornerContacts, AlongACrackThroughTheNodeTheCornersAcrossItKeepTheirContacts) {
  System system(make_node({0, 3}));
  system.step();
  const auto side = [](int block) { return block < 3 ? 0 : 1; };
  int across_on_intact_faces = 0;
  for (const ContactInfo& c : system.contacts()) {
    const int apart = (c.key.block_j - c.key.block_i + kTriangles) % kTriangles;
    if (c.key.vertex != 0 || apart == 1 || apart == kTriangles - 1) continue;
    const int bond = system.bond_of_contact(c.key);
    ASSERT_GE(bond, 0) << "a corner at the node against a spoke";
    if (!system.is_bond_broken(bond) && side(c.key.block_i) != side(c.key.block_j)) ++across_on_intact_faces;
  }
  EXPECT_GT(across_on_intact_faces, 0);
}

// A crack through the node on spokes 0 and 4: triangles 0-3 on one side, 4 and 5 on the other,
// the corners parted as a crack's opening parts them: triangle 3's corner (beside the crack, its
// face on spoke 4 broken) moved 2 ties along triangle 0's face on the crack (spoke 0, across the
// node from it) and 0.75 tie past that face's line, into triangle 0's corner, as the resolved
// seal's corner stood at 1,200 m over hydrostatic (a corner 7.5e-7 m past the end of a broken
// face two sub-blocks away on its side of a crack, a contact of no tributary length whose forces
// never settled). Triangles 1 and 2, bonded to both, stand between: the broken face's end is
// the far side's to touch (triangle 5's), and triangle 3's corner has no contact with it.
TEST(NodeCornerContacts, AlongACrackThroughTheNodeACornerBesideItDoesNotTouchABrokenFaceOnItsOwnSide) {
  ModelDefinition m = make_node({0, 4});
  m.settings.contact_distance = 1.0e-3;
  const double tie = 1.0e-3 * m.settings.contact_distance;  // contact_detection.cpp's corner tie
  const Point centre = m.blocks[0].polygon[0];
  const Point along = m.blocks[0].polygon[1] - centre;  // triangle 0's face on spoke 0
  const Point t = along / std::hypot(along.x, along.y);
  const Point inward{-t.y, t.x};  // into triangle 0 (counter-clockwise)
  m.blocks[3].polygon[0] = centre + 2.0 * tie * t + 0.75 * tie * inward;
  System system(m);
  system.step();
  int from_its_own_side = 0, from_the_far_side = 0;
  for (const ContactInfo& c : system.contacts()) {
    if (system.bond_of_contact(c.key) != 0 || (c.key.block_i != 0 && c.key.block_j != 0)) continue;
    const int other = c.key.block_i == 0 ? c.key.block_j : c.key.block_i;
    if (other == 3) ++from_its_own_side;
    if (other == kTriangles - 1) ++from_the_far_side;
  }
  EXPECT_EQ(from_its_own_side, 0);
  EXPECT_GT(from_the_far_side, 0);
}

// A block built without bonds of its own (its edge_bonds left empty, as a model built in code
// may leave it) at a node of bonded sub-blocks: the rule reads its faces at the corner as faces
// of no bond, as it reads a scenario's blocks, whose edge_bonds hold −1. Triangle 0 is such a
// block, spokes 0 and 1 joints; the others are bonded along spokes 2–5 (renumbered 0–3). The
// two models step to the same contacts (exact identity).
TEST(NodeCornerContacts, ABlockWithoutBondsAtANodeOfBondedSubBlocksIsReadAsFacesOfNoBond) {
  const auto model = [](std::vector<int> plain_bonds) {
    ModelDefinition m = make_node({});
    for (BlockDefinition& b : m.blocks)
      for (int& bond : b.edge_bonds) bond = bond <= 1 ? -1 : bond - 2;
    m.blocks.front().edge_bonds = std::move(plain_bonds);
    return m;
  };
  System empty(model({})), filled(model({-1, -1, -1}));
  empty.step();
  filled.step();
  ASSERT_EQ(empty.contacts().size(), filled.contacts().size());
  for (std::size_t i = 0; i < empty.contacts().size(); ++i) {
    EXPECT_EQ(empty.contacts()[i].key, filled.contacts()[i].key) << i;
    EXPECT_EQ(empty.contacts()[i].state, filled.contacts()[i].state) << i;
  }
  int from_the_plain_corner = 0;
  for (const ContactInfo& c : empty.contacts()) from_the_plain_corner += c.key.block_i == 0 && c.key.vertex == 0 ? 1 : 0;
  EXPECT_GT(from_the_plain_corner, 0);
}

// How deep the deepest vertex of one triangle lies inside another (0: none inside).
double deepest_overlap(const System& system) {
  double deepest = 0.0;
  for (int a = 0; a < kTriangles; ++a)
    for (int b = 0; b < kTriangles; ++b) {
      if (a == b) continue;
      const Polygon& into = system.polygon(b);
      for (const Point p : system.polygon(a)) {
        if (!geometry::contains(into, p)) continue;
        double depth = INFINITY;  // to the nearest edge
        for (std::size_t e = 0; e < into.size(); ++e)
          depth = std::min(depth, geometry::distance_to_segment(p, into[e], into[(e + 1) % into.size()]));
        deepest = std::max(deepest, depth);
      }
    }
  return deepest;
}

// Bonds that break in a step free their corners' contacts in that step where the step would
// otherwise run a corner into a block (System::breaks_let_corners_in): triangles 3 and 4 fixed,
// triangle 1 driven down into the node like a wedge (1e5 N at each of its ring corners), weak
// bonds. It splits its neighbours off (spokes 1, 2 break, and the faces beyond them), and its
// tip, which had no contact with the fixed triangles across the node while its faces held (tip
// to tip within intact rock), is driven at them. The step ends as the same step from a start
// with those bonds broken: the same contacts, the same motion (exact identity up to the solve's
// round-off, 1e-12 of the motion), and no corner inside a neighbour beyond the penetration
// tolerance. Without the rule the step went on with the contacts found while the bonds held and
// a corner ended 7.4 µm inside a neighbour, against a tolerance of 0.85 µm (at a node of three
// cracks in the strip seal of tutorial_intact_seal.md, a corner ran 27 µm into the sub-block
// across the node).
TEST(NodeCornerContacts, BondsThatBreakInAStepFreeTheirCornersContactsInThatStep) {
  const auto model = [](const std::vector<int>& broken) {
    ModelDefinition m = make_node(broken);
    m.joint_types = {Joint{25.0, 1.0e4, 1.0e4}};
    m.blocks[3].fixed = m.blocks[4].fixed = true;
    return m;
  };
  const auto drive = [](System& system) {
    std::vector<std::vector<Point>> forces(kTriangles, std::vector<Point>(3, Point{0.0, 0.0}));
    forces[1][1] = forces[1][2] = {0.0, -1.0e5};
    system.set_vertex_forces(forces);
  };
  System breaking(model({}));
  drive(breaking);
  const StepReport report = breaking.step();
  std::vector<int> broke;
  for (const BondBreak& b : breaking.bond_breaks()) broke.push_back(b.bond);
  ASSERT_FALSE(broke.empty()) << "no bond broke";
  EXPECT_GE(report.tries_with_bonds_broken, 1);
  EXPECT_LE(deepest_overlap(breaking), breaking.penetration_tolerance());
  System broken(model(broke));
  drive(broken);
  broken.step();
  const std::vector<ContactInfo> a = breaking.contacts(), b = broken.contacts();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].key, b[i].key) << i;
    EXPECT_EQ(a[i].state, b[i].state) << i;
  }
  double scale = 0.0;
  for (int block = 0; block < kTriangles; ++block)
    scale = std::max(scale, std::hypot(broken.displacement(block).x, broken.displacement(block).y));
  ASSERT_GT(scale, 0.0);
  for (int block = 0; block < kTriangles; ++block) {
    EXPECT_NEAR(breaking.displacement(block).x, broken.displacement(block).x, 1e-12 * scale) << block;
    EXPECT_NEAR(breaking.displacement(block).y, broken.displacement(block).y, 1e-12 * scale) << block;
  }
}

}  // namespace
}  // namespace hydrodda::dda
