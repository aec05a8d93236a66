// Contact detection: the grid broad phase against all pairs, the narrow phase on exact cases.

#include "dda/contact_detection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using geometry::Box;
using testing::make_rectangle;

// The face length the contacts carry between them (what cohesion and tensile strength act on);
// `polygons` by block id.
double total_length(const ContactCandidates& found, const std::vector<Polygon>& polygons, double distance) {
  double total = 0.0;
  for (const ContactCandidate& c : found)
    total += tributary_length(polygons[c.key.block_i], c.key.vertex, polygons[c.key.block_j], c.key.edge, distance);
  return total;
}

// Two blocks sharing `length` of face: one vertex–edge contact at each end of the shared part,
// their tributary lengths summing to `length` (to 1e-12), with the pair given either way round.
void expect_face_counted_once(const Polygon& a, const Polygon& b, double length) {
  for (bool swapped : {false, true}) {
    ContactCandidates found;
    if (swapped)
      find_pair_contacts(b, 1, a, 0, 0.01, found);
    else
      find_pair_contacts(a, 0, b, 1, 0.01, found);
    EXPECT_EQ(found.size(), 2u) << (swapped ? "b against a" : "a against b");
    EXPECT_NEAR(total_length(found, {a, b}, 0.01), length, 1e-12) << (swapped ? "b against a" : "a against b");
  }
}

// The grid finds exactly the pairs an all-pairs check finds (random boxes, sizes 0.1–3).
TEST(ContactDetection, BroadPhaseEqualsAllPairs) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 30.0);
  std::uniform_real_distribution<double> size(0.1, 3.0);
  std::vector<Box> boxes;
  for (int i = 0; i < 400; ++i) {
    const Point lo{pos(rng), pos(rng)};
    boxes.push_back({lo, lo + Point{size(rng), size(rng)}});
  }
  std::vector<char> skip(boxes.size(), 0);
  skip[3] = skip[5] = 1;
  const double d = 0.2;
  std::vector<std::pair<int, int>> expected;
  for (int i = 0; i < 400; ++i)
    for (int j = i + 1; j < 400; ++j)
      if (!(skip[i] && skip[j]) && boxes[i].inflated(d).overlaps(boxes[j])) expected.emplace_back(i, j);
  EXPECT_EQ(find_block_pairs(boxes, d, skip), expected);
}

// A square resting on a wider one: its two bottom vertices touch the top edge (index 2),
// each carrying half of the 1 m face; the lower block's top vertices are out of range.
TEST(ContactDetection, FaceContactFindsBothVerticesWithHalfLengths) {
  const Polygon base = make_rectangle(-5, -1, 5, 0);
  const Polygon top = make_rectangle(0, 0.001, 1, 1.001);
  ContactCandidates found;
  find_pair_contacts(base, 0, top, 1, 0.01, found);
  ASSERT_EQ(found.size(), 2u);
  for (const ContactCandidate& c : found) {
    EXPECT_EQ(c.key.block_i, 1);
    EXPECT_EQ(c.key.block_j, 0);
    EXPECT_EQ(c.key.edge, 2);
    EXPECT_NEAR(c.penetration, -0.001, 1e-12);
    EXPECT_NEAR(tributary_length(top, c.key.vertex, base, c.key.edge, 0.01), 0.5, 1e-12);
  }
}

// Two equal squares side by side, corners coinciding: the shared 1 m face is one edge–edge
// contact, a vertex–edge contact at each end of it, so the tributary lengths (what cohesion
// and tensile strength act on) sum to the face's length, 1 m to 1e-12, not twice it, whichever
// block the pair names first.
TEST(ContactDetection, CoincidingCornersCountTheFaceOnce) {
  expect_face_counted_once(make_rectangle(0, 0, 1, 1), make_rectangle(1, 0, 2, 1), 1.0);
}

// Bricks offset by half a length, one on the other: the 1 m overlap of their faces is one
// vertex–edge contact at each end of it (the upper brick's corner on the lower face, the lower
// brick's corner on the upper face), each carrying half the overlap, so cohesion and tensile
// strength act on 1 m (to 1e-12), not on both faces' lengths, whichever block the pair names
// first.
TEST(ContactDetection, OffsetFacesCountTheOverlapOnce) {
  expect_face_counted_once(make_rectangle(0, 0, 2, 1), make_rectangle(1, 1, 3, 2), 1.0);
}

// A corner that lies on the line of two edges of the other block (side-by-side bricks) has
// two candidate entrance edges at equal gaps: the one carrying the face contact is taken,
// whatever the round-off, so the contact keeps its key from step to step.
TEST(ContactDetection, CornerOnTwoEdgeLinesTakesTheFaceEdge) {
  const Polygon left = make_rectangle(0, 0, 1, 1);
  for (double wobble : {-1e-13, 0.0, 1e-13}) {
    const Polygon right = make_rectangle(1 + wobble, wobble, 2, 1);
    ContactCandidates found;
    find_pair_contacts(left, 0, right, 1, 0.01, found);
    ASSERT_EQ(found.size(), 2u) << wobble;
    for (const ContactCandidate& c : found)
      EXPECT_TRUE((c.key.block_j == 1 && c.key.edge == 3) || (c.key.block_j == 0 && c.key.edge == 1))
          << "wobble " << wobble << ": vertex " << c.key.vertex << " on edge " << c.key.edge;
  }
}

// Blocks diagonally across a junction of joints meet corner to corner only: neither edge at the
// corner carries any face (both tributary lengths are 0), so the lower index breaks the tie.
// Moved by round-off (shifted by up to 1e-13 m each way, turned by 1e-12 rad about the corner),
// the corner lies a hair past one edge's end or the other's, a "face" of 1e-13 m on one edge
// and none on the other; the contact keeps the same vertex and edge all the same. (A flip from
// step to step between the two edges re-keys the contact and throws the kept factor away.)
TEST(ContactDetection, CornerOnCornerKeepsItsEdgeWhateverTheRoundOff) {
  const Polygon below = make_rectangle(0, 0, 1, 1);
  std::vector<std::array<int, 4>> keys;
  for (double dx : {-1e-13, 0.0, 1e-13})
    for (double dy : {-1e-13, 0.0, 1e-13})
      for (double turn : {-1e-12, 0.0, 1e-12}) {
        Polygon above;
        for (Point p : make_rectangle(1, 1, 2, 2)) {
          const Point r = p - Point{1, 1};
          above.push_back(Point{1 + dx, 1 + dy} + Point{r.x * std::cos(turn) - r.y * std::sin(turn),
                                                        r.x * std::sin(turn) + r.y * std::cos(turn)});
        }
        ContactCandidates found;
        find_pair_contacts(below, 0, above, 1, 0.01, found);
        ASSERT_EQ(found.size(), 1u) << "dx " << dx << ", dy " << dy << ", turn " << turn;
        const ContactKey& k = found[0].key;
        keys.push_back({k.block_i, k.vertex, k.block_j, k.edge});
      }
  for (const auto& key : keys) EXPECT_EQ(key, keys.front());
  EXPECT_EQ(keys.front(), (std::array<int, 4>{0, 2, 1, 0}));  // below's corner (1, 1) on above's bottom edge
}

// Two straight joints crossing at X = (0, 0), 60° apart (the faulted seal's conjugate sets),
// cut four blocks whose corners meet there. The block above (its corner pointing down) has
// slid up along one joint line by s and across it by 1e-5 m, as the blocks beside it allow:
// the lower block's corner now lies past the upper block's corner, 1e-5 m behind the line of
// its lower-left edge and outside the line of its lower-right edge, so outside it. Within the
// corner tie (1e-3 of the contact distance, 5.6e-4 m at the seal's 0.56 m) the lower index
// took the edge it lies behind: a contact 1e-5 m deep that no force could push out, on which
// the seal's DDA step at 2,000 m of head failed. The corner touches the edge it is outside of,
// standing off it; that holds at any tie (two contact distances).
TEST(ContactDetection, ACornerPastTheDiagonalCornerIsNoPenetration) {
  const double c60 = 0.5, s60 = std::sqrt(3.0) / 2.0;
  const Point up_right{c60, s60}, up_left{-c60, s60};  // the two joint lines through X
  const Point across{s60, c60};                         // normal to the up-left line, into the upper block
  // Counter-clockwise, each with its corner at X; the upper block's lower-left edge first, so
  // that the edge the lower corner lies behind has the lower index of the two at the corner.
  const Polygon lower{Point{0, 0}, -4.0 * up_right, Point{0, -6.93}, -4.0 * up_left};
  for (double distance : {0.56, 0.01}) {
    for (double slide : {2e-5, 1e-4}) {
      const Point shift = slide * up_left - 1e-5 * across;  // up the joint, and 1e-5 m across it
      const Polygon upper{4.0 * up_left + shift, shift, 4.0 * up_right + shift, Point{0, 6.93} + shift};
      ContactCandidates found;
      find_pair_contacts(lower, 0, upper, 1, distance, found);
      EXPECT_FALSE(found.empty()) << "the corners are within the contact distance " << distance;
      for (const ContactCandidate& c : found)
        EXPECT_LE(c.penetration, 0.0) << "distance " << distance << ", slide " << slide << ": vertex " << c.key.vertex
                                      << " of block " << c.key.block_i << " on edge " << c.key.edge << " reads "
                                      << c.penetration << " m deep";
    }
  }
}

// A corner standing a hair past another block's corner, on the line of that block's face: the
// bed's corner where a steep joint meets the notched seal through intact rock stood 1.5e-7 m
// beyond a node of the rock's face and 8.7e-8 m below its line, and the entrance-edge rule gave
// it a contact with the face a hair before the node and none a hair past it. Without a depth to
// keep, no candidate on that face (the rule as it was); with one, a candidate marked
// kept_if_closed, for the caller to keep by the contact's last state; none past the corner tie
// (1e-3 of the contact distance, here 1e-5 m) nor deeper behind the line than the depth.
TEST(ContactDetection, ACornerAHairPastACornerOnItsFaceIsACandidateKeptOnlyIfClosed) {
  const Polygon rock = make_rectangle(0, -1, 1, 0);  // edge 2 its top face, from (1, 0) to the corner (0, 0)
  const auto bed = [](double past, double below) {
    // Counter-clockwise; vertex 1 its corner, its bottom face running left along y = -below.
    return Polygon{{-2, -below}, {-past, -below}, {0.5, 3}, {-2, 3}};
  };
  const auto on_top_face = [&](const Polygon& above, double kept_depth) {
    ContactCandidates found;
    // The bed first: a's corners are kept where b's coincide with them (CoincidingCornersCountTheFaceOnce).
    find_pair_contacts(above, 0, rock, 1, 0.01, found, kept_depth);
    std::vector<ContactCandidate> on_top;
    for (const ContactCandidate& c : found)
      if (c.key.block_i == 0 && c.key.vertex == 1 && c.key.block_j == 1 && c.key.edge == 2) on_top.push_back(c);
    return on_top;
  };
  EXPECT_TRUE(on_top_face(bed(1.5e-7, 8.7e-8), kNoCornerMemory).empty());
  const auto kept = on_top_face(bed(1.5e-7, 8.7e-8), 1e-7);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept[0].kept_if_closed);
  EXPECT_NEAR(kept[0].penetration, 8.7e-8, 1e-15);
  EXPECT_TRUE(on_top_face(bed(2e-5, 8.7e-8), 1e-7).empty());   // past the tie: beyond the node
  EXPECT_TRUE(on_top_face(bed(1.5e-7, 2e-7), 1e-7).empty());   // deeper than the depth kept
  // A hair before the node, over the face: a contact of its own, whatever the depth.
  for (double depth : {kNoCornerMemory, 1e-7}) {
    const auto over = on_top_face(bed(-1.5e-7, 8.7e-8), depth);
    ASSERT_EQ(over.size(), 1u);
    EXPECT_FALSE(over[0].kept_if_closed);
  }
}

// Vertex–vertex: a wedge's corner near a square's corner from the diagonal takes one
// entrance edge, the one whose line it is farther outside; the square's corner, whose
// material would lie inside the wedge's edge lines, is not taken against the wedge.
TEST(ContactDetection, VertexToVertexTakesTheEntranceEdge) {
  const Polygon square = make_rectangle(0, 0, 1, 1);
  // Wedge with its corner at (1.002, 1.001): farther outside x = 1 than y = 1.
  const Polygon diamond{{1.002, 1.001}, {1.602, 1.201}, {1.602, 1.601}, {1.202, 1.601}};
  ContactCandidates found;
  find_pair_contacts(square, 0, diamond, 1, 0.01, found);
  int from_diamond = 0;
  for (const ContactCandidate& c : found)
    if (c.key.block_i == 1) {
      ++from_diamond;
      EXPECT_EQ(c.key.edge, 1);  // the square's right edge (1,0) → (1,1)
    }
  EXPECT_EQ(from_diamond, 1);
  EXPECT_EQ(found.size(), 1u);
}

// Contact distances near a block's size (a tall model's default, or a large ratio): two
// blocks 1 mm apart across a slanting joint. The left block's corner (1, 0.6) lies 0.6 m
// behind the line of the right block's bottom edge, projecting onto it 0.1 m from its start,
// and the right block's corner (0.9, 0) 0.6 m behind the line of the left block's top edge.
// Neither is inside the other block, so neither is a contact with those far edges (taken for
// one, a 0.6 m penetration no step could settle); the left corner's contact is with the
// joint, 1 mm away.
TEST(ContactDetection, ACornerBesideABlockIsNoContactWithItsFarEdges) {
  const double run = 0.101 / 0.6;  // the joint's run per metre of rise
  const Polygon left{{0.0, -0.4}, {0.899 - 0.4 * run, -0.4}, {1.0, 0.6}, {0.0, 0.6}};
  const Polygon right{{0.9, 0.0}, {2.0, 0.0}, {2.0, 0.6}, {1.001, 0.6}};  // edge 3 is the joint
  for (const double distance : {0.01, 0.7}) {
    ContactCandidates found;
    find_pair_contacts(left, 0, right, 1, distance, found);
    int corner_contacts = 0;
    for (const ContactCandidate& c : found) {
      EXPECT_LE(c.penetration, 0.0) << "distance " << distance << ": vertex " << c.key.vertex << " of block "
                                    << c.key.block_i << " on edge " << c.key.edge;
      if (c.key.block_i == 0 && c.key.vertex == 2) {
        ++corner_contacts;
        EXPECT_EQ(c.key.edge, 3) << "distance " << distance;
      }
    }
    EXPECT_EQ(corner_contacts, 1) << "distance " << distance;
  }
}

// A corner 2 mm inside a block through its bottom edge, 0.7 m from its left edge, with a
// contact distance of 1 m: it entered by the bottom edge, the nearest, and is a contact with
// that edge alone, penetrating 2 mm (to 1e-12), not 0.7 m into the left one.
TEST(ContactDetection, ACornerInsideABlockTouchesTheEdgeItEnteredBy) {
  const Polygon lower = make_rectangle(0.1, 0.0, 0.7, 1.002);  // corners 2 and 3 at y = 1.002
  const Polygon upper = make_rectangle(0.0, 1.0, 0.8, 1.6);    // bottom edge 0 at y = 1
  ContactCandidates found;
  find_pair_contacts(lower, 0, upper, 1, 1.0, found);
  int from_lower = 0;
  for (const ContactCandidate& c : found)
    if (c.key.block_i == 0) {
      ++from_lower;
      EXPECT_EQ(c.key.edge, 0) << "vertex " << c.key.vertex;
      EXPECT_NEAR(c.penetration, 0.002, 1e-12) << "vertex " << c.key.vertex;
    }
  EXPECT_EQ(from_lower, 2);
}

// A bed whose top is split into collinear edges where joints from above meet it, 0.1 m apart,
// under a contact distance of 0.2 m. The corner of the block above at one junction, (1, 1),
// lies on the line of the edge beyond the next junction, (3, 1) → (1.1, 1), past its end by
// 0.1 m. It touches the bed where it stands, on the edges that meet there; the far edge's end
// is not its nearest point of the bed, so it is no contact with that edge (taken, it would be
// a contact 0.1 m from any face of its own, started locked under whatever the bed carries).
// The same for the right block's corner (1.1, 1) and the edge (1, 1) → (0, 1).
TEST(ContactDetection, ACornerAtAJunctionIsNoContactWithTheCollinearEdgeBeyond) {
  const Polygon bed{{0, 0}, {3, 0}, {3, 1}, {1.1, 1}, {1, 1}, {0, 1}};  // top edges 2, 3, 4
  const std::vector<Polygon> above{make_rectangle(0, 1, 1, 2), make_rectangle(1.1, 1, 3, 2)};
  const double distance = 0.2;
  for (int side = 0; side < 2; ++side) {
    ContactCandidates found;
    find_pair_contacts(above[side], 0, bed, 1, distance, found);
    const Point corner = side == 0 ? Point{1, 1} : Point{1.1, 1};
    int at_corner = 0;
    for (const ContactCandidate& c : found) {
      if (c.key.block_i != 0) continue;
      const Point p = above[side][c.key.vertex];
      if (geometry::distance(p, corner) > 1e-12) continue;
      ++at_corner;
      const int far_edge = side == 0 ? 2 : 4;
      EXPECT_NE(c.key.edge, far_edge) << "the corner at " << p.x << " taken against the edge beyond";
    }
    EXPECT_GE(at_corner, 1) << "side " << side << ": the corner touches the bed where it stands";
  }
}

// A reflex (concave) vertex never touches a face: an L-shaped block's inner corner above a
// flat top edge is not a contact, its convex vertices are.
TEST(ContactDetection, ReflexVertexIsNotAContact) {
  const Polygon l_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const Polygon lid = make_rectangle(1.0, 1.0 + 1e-4, 3, 2);  // sits on the L's inner step
  ContactCandidates found;
  find_pair_contacts(l_shape, 0, lid, 1, 0.01, found);
  for (const ContactCandidate& c : found)
    if (c.key.block_i == 0) {
      EXPECT_NE(c.key.vertex, 3) << "reflex vertex (1,1) taken";
    }
  EXPECT_FALSE(found.empty());
}

// Expects vertex `vertex` of block 1 among `found` to touch edge `edge` of block 0, `depth`
// behind its line (within `tolerance`).
void expect_tip_on_edge(const ContactCandidates& found, int vertex, int edge, double depth, double tolerance) {
  const auto tip = std::find_if(found.begin(), found.end(),
                                [&](const ContactCandidate& c) { return c.key.block_i == 1 && c.key.vertex == vertex; });
  ASSERT_NE(tip, found.end());
  EXPECT_EQ(tip->key.block_j, 0);
  EXPECT_EQ(tip->key.edge, edge);
  EXPECT_NEAR(tip->penetration, depth, tolerance);
}

// A thin wedge's tip (a sub-block of 10° whose bonds had all broken, beside the strip seal's
// crack) that entered a triangle by their shared face near its end, 1.16 mm behind that face
// and 0.62 mm behind the triangle's other edge at the corner: the other edge is the nearer,
// but the wedge's own block lies across its line, so the tip cannot have come in by it. The
// face is the entrance edge, with the tip's depth behind it as the penetration (to 1e-6 m,
// the coordinates' digits); before, the nearer edge was taken as the entrance and then refused
// by the wedge test, leaving the tip no contact at all, and it ran on into the triangle by
// millimetres a step until the step failed.
TEST(ContactDetection, AWedgesTipPastAFacesEndEntersByTheFaceItsBlockCanTouch) {
  const std::vector<Point> triangle{{0.005415, 0.396097}, {0.190718, 0.147996}, {0.173636, 0.343179}};
  const std::vector<Point> wedge{{0.192567, 0.147960}, {0.230583, 0.134026}, {0.172498, 0.342866}};
  ContactCandidates found;
  find_pair_contacts(triangle, 0, wedge, 1, 0.002, found);
  expect_tip_on_edge(found, 2, 1, 1.161e-3, 1e-6);
}

// Two corners tip to tip (sub-blocks of the Brazilian disc at D/40 in its cascade past the
// peak): vertex 1 of the upper triangle lies 19 µm from the lower triangle's corner, 14 µm
// behind the line of its edge 0 and 4 µm behind that of its edge 2. The upper triangle lies
// wholly outside edge 0 near its tip but straddles the line of edge 2 beyond the corner, so
// the tip can push only on edge 0: that is its contact, at its depth behind it (to 1e-9 m, the
// coordinates' digits), though edge 2 is the nearer.
TEST(ContactDetection, ATipPastACornerPushesOnTheFaceItsBlockLiesOutside) {
  const std::vector<Point> lower{{0.049581712, 0.231489739}, {0.046126297, 0.227216401}, {0.056196001, 0.213463710}};
  const std::vector<Point> upper{{0.030569152, 0.248335465}, {0.049584343, 0.231470795}, {0.045413071, 0.251505801}};
  ContactCandidates found;
  find_pair_contacts(lower, 0, upper, 1, 8.328e-5, found);
  expect_tip_on_edge(found, 1, 0, 1.3957e-5, 1e-9);
}

// Two sub-blocks of a tessellated rock at a node (the strip seal's, by its crack), their
// corners a hair apart along the line they both lie on one side of: vertex 2 of the left one
// stands 7 nm behind the line of the right one's edge 1, 64 µm short of that edge's end at the
// right one's 11° tip, and so 12 µm behind the line of its edge 2, across the sliver. Its own
// block lies across edge 1's line (they lie on the same side of it), but the vertex is on
// that edge, within the corner tie (1e-3 of the contact distance): it stands on the block's
// boundary and entered by neither edge. Given a contact on edge 2, 12 µm deep, the strip
// seal's step failed, its contact forces never settling.
TEST(ContactDetection, ACornerOnTheLineOfANeighboursEdgeAtANodeIsNoContactWithTheEdgeBehind) {
  const std::vector<Point> left{{5.936756653, 5.859959735}, {6.266361218, 5.953068981}, {6.070464229, 6.013364427}};
  const std::vector<Point> right{{6.230099477, 6.133508480}, {6.192261738, 6.148011061}, {6.070421335, 6.013317018}};
  ContactCandidates found;
  find_pair_contacts(left, 0, right, 1, 1.889e-3, found);
  for (const ContactCandidate& c : found) {
    if (c.key.block_i == 0 && c.key.vertex == 2) {
      EXPECT_NE(c.key.edge, 2) << "penetration " << c.penetration;
    }
  }
}

}  // namespace
}  // namespace hydrodda::dda
