// The ends of an intact bonded face (System::drop_second_contacts_at_intact_face_ends): a face is
// carried by one vertex–edge contact at each end (Shi 1988, §4.3). Where its two sub-blocks'
// corners at an end lie within the corner tie (a thousandth of the contact distance) of each
// other, the search counts them as one corner; farther apart along the face (beside a crack's
// opening tip), one lies within the other's edge and one past its end, and the one past the end
// was kept while within the tie of the line of the other block's next edge. At the seal's flaw
// tip the two corners lay 0.67 and 1.33 ties apart in turn: one contact, then two (the second
// locked, pulling them together), then one, and the step never came to rest. The end's contact
// must be the same wherever the corner past the end lies.
// Exact: the contacts are counted and their keys compared, no tolerance.

#include <gtest/gtest.h>

#include <vector>

#include "dda/system.hpp"

namespace hydrodda::dda {
namespace {

constexpr double kContactDistance = 1.0e-3;     // m
constexpr double kTie = 1.0e-3 * kContactDistance;  // contact_detection.cpp's corner tie

// Two triangles bonded along y = 0 from x = −1 to 0: block 0 below (its edge 0 the face, from
// (0, 0) to (−1, 0); its edge 2 a face 50° off it, rising to (0, 0)), block 1 above (its edge 0
// the face, from (−1, 0) to (offset, 0)): block 1's corner at the right-hand end lies `offset`
// past block 0's, outside the line of block 0's edge 2 by 0.77 offset.
ModelDefinition make_offset_face(double offset) {
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  BlockDefinition below{{{0.0, 0.0}, {-1.0, 0.0}, {-0.5, -0.6}}, 0, false};
  below.edge_joints = {1, 0, 0};
  below.edge_bonds = {0, -1, -1};
  BlockDefinition above{{{-1.0, 0.0}, {offset, 0.0}, {-0.5, 0.6}}, 0, false};
  above.edge_joints = {1, 0, 0};
  above.edge_bonds = {0, -1, -1};
  m.blocks = {below, above};
  m.joint = {30.0, 0.0, 0.0};
  m.joint_types = {Joint{25.0, 6.0e6, 2.0e6}};
  m.settings.analysis = Analysis::static_;
  m.settings.gravity = {0.0, 0.0};
  m.settings.time_step = 1e-3;
  m.settings.contact_distance = kContactDistance;
  return m;
}

// The contacts on the bonded face whose vertex lies at its right-hand end, x ≥ −0.5.
std::vector<ContactKey> contacts_at_right_end(const System& system) {
  std::vector<ContactKey> out;
  for (const ContactInfo& c : system.contacts()) {
    if (system.bond_of_contact(c.key) != 0) continue;
    const Point p = system.polygon(c.key.block_i)[static_cast<std::size_t>(c.key.vertex)];
    if (p.x >= -0.5) out.push_back(c.key);
  }
  return out;
}

TEST(BondedFaceEnd, ItsEndIsCarriedByTheCornerWithinTheOtherEdgeWhereverTheOtherCornerLies) {
  // 0.5 tie: one corner to the search; 1.2 tie: two corners, block 1's within the tie of the line
  // of block 0's edge 2 (0.92 tie); 2.5 tie: block 1's outside that line by 1.9 ties.
  const ContactKey within{0, 0, 1, 0};  // block 0's corner on block 1's face
  for (const double offset : {0.5 * kTie, 1.2 * kTie, 2.5 * kTie}) {
    System system(make_offset_face(offset));
    system.step();
    const std::vector<ContactKey> at_end = contacts_at_right_end(system);
    ASSERT_EQ(at_end.size(), 1u) << "offset " << offset << " m";
    EXPECT_EQ(at_end.front(), within) << "offset " << offset << " m";
  }
}

TEST(BondedFaceEnd, ABrokenFaceKeepsBothCorners) {
  // Broken, the face is a joint's: the corner past the end is a contact of its own (the search's
  // entrance-edge rule alone), as on any joint.
  ModelDefinition m = make_offset_face(1.2 * kTie);
  m.broken_bonds = {0};
  System system(m);
  system.step();
  EXPECT_EQ(contacts_at_right_end(system).size(), 2u);
}

}  // namespace
}  // namespace hydrodda::dda
