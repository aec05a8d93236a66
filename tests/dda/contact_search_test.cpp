// The contact search with kept lists: the same candidates as a search of all pairs, step
// after step, while the lists are kept and after they are made again.

#include "dda/contact_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_random_packing;
using testing::make_rectangle;

// Every pair (i < j, not both fixed) through find_pair_contacts, sorted by key: the reference.
ContactCandidates search_all_pairs(const std::vector<Polygon>& polygons, const std::vector<char>& fixed,
                                   double distance) {
  ContactCandidates out;
  for (std::size_t i = 0; i < polygons.size(); ++i)
    for (std::size_t j = i + 1; j < polygons.size(); ++j)
      if (!(fixed[i] && fixed[j]))
        find_pair_contacts(polygons[i], static_cast<int>(i), polygons[j], static_cast<int>(j), distance, out);
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.key < y.key; });
  return out;
}

ContactCandidates search(ContactSearch& s, const std::vector<Polygon>& polygons, const std::vector<char>& fixed) {
  std::vector<std::span<const Point>> views(polygons.begin(), polygons.end());
  ContactCandidates out;
  s.find(views, fixed, out);
  return out;
}

// Exactly equal: the same keys and the same bits in every field.
void expect_same(const ContactCandidates& found, const ContactCandidates& expected, int round) {
  ASSERT_EQ(found.size(), expected.size()) << "round " << round;
  for (std::size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(found[k].key, expected[k].key) << "round " << round;
    EXPECT_EQ(found[k].edge_ratio, expected[k].edge_ratio) << "round " << round;
    EXPECT_EQ(found[k].penetration, expected[k].penetration) << "round " << round;
  }
}

// A 12 × 12 lattice of jittered quadrilaterals 0.5 mm apart on a fixed base (the random
// packing), each moved every round by its own small rigid motion (translation and rotation
// about its centroid). The search is told the largest vertex motion, as a DDA step tells it;
// its candidates equal an all-pairs search's in every round, exactly. Small motions keep the
// lists for several rounds; larger ones make them again; both happen here.
TEST(ContactSearch, FindsWhatASearchOfAllPairsFindsWhileTheBlocksMove) {
  std::vector<Polygon> polygons;
  std::vector<char> fixed;
  for (const BlockDefinition& b : make_random_packing(12).blocks) {
    polygons.push_back(b.polygon);
    fixed.push_back(b.fixed ? 1 : 0);
  }
  std::mt19937 rng(2024);
  const double distance = 0.02;
  ContactSearch kept(distance, 0.2 * distance);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int round = 0; round < 40; ++round) {
    expect_same(search(kept, polygons, fixed), search_all_pairs(polygons, fixed, distance), round);
    // Rounds 10–19 and 30–39 move by up to 4 mm (lists made again every round or two);
    // the others by up to 0.2 mm (kept for about ten rounds).
    const double size = (round / 10) % 2 == 1 ? 4e-3 : 2e-4;
    double largest = 0.0;
    for (std::size_t b = 1; b < polygons.size(); ++b) {
      const Point shift{size * unit(rng) / 2, size * unit(rng) / 2};
      const double angle = size * unit(rng) / 4;  // radius under 1 m: a vertex moves under size / 4
      const Point c = geometry::centroid(polygons[b]);
      for (Point& v : polygons[b]) {
        const Point r = v - c;
        const Point moved = c + Point{std::cos(angle) * r.x - std::sin(angle) * r.y,
                                      std::sin(angle) * r.x + std::cos(angle) * r.y} + shift;
        largest = std::max(largest, geometry::distance(moved, v));
        v = moved;
      }
    }
    kept.add_motion(largest);
  }
  // Kept through most of the slow rounds, made again in most of the fast ones.
  EXPECT_GT(kept.list_count(), 12);
  EXPECT_LT(kept.list_count(), 30);
}

// At the margin: a square whose corner is just beyond the contact distance plus the skin from
// the base is not listed; moved half the skin toward it, it is still beyond the contact
// distance, and the kept lists rightly find nothing; moved past half the skin, the lists are
// made again and the contact found.
TEST(ContactSearch, MotionPastHalfTheSkinMakesTheListsAgain) {
  const double distance = 0.01;
  const double skin = 0.004;
  const std::vector<char> fixed{1, 0};
  ContactSearch s(distance, skin);
  const auto square_at = [](double gap) { return make_rectangle(0.0, gap, 1.0, 1.0 + gap); };
  const Polygon base = make_rectangle(-2.0, -1.0, 3.0, 0.0);
  double gap = distance + skin + 1e-6;
  EXPECT_TRUE(search(s, {base, square_at(gap)}, fixed).empty());
  EXPECT_EQ(s.list_count(), 1);
  gap -= 0.5 * skin;
  s.add_motion(0.5 * skin);
  EXPECT_TRUE(search(s, {base, square_at(gap)}, fixed).empty());
  EXPECT_EQ(s.list_count(), 1);
  gap -= 0.5 * skin + 2e-6;
  s.add_motion(0.5 * skin + 2e-6);
  // Both bottom corners, 1e-6 inside the contact distance.
  EXPECT_EQ(search(s, {base, square_at(gap)}, fixed).size(), 2u);
  EXPECT_EQ(s.list_count(), 2);
}

// Forgetting the lists makes them again at the next search, motion or not.
TEST(ContactSearch, ForgetMakesTheListsAgain) {
  ContactSearch s(0.01, 0.002);
  const std::vector<Polygon> polygons{make_rectangle(0, 0, 1, 1), make_rectangle(1.005, 0, 2, 1)};
  const std::vector<char> fixed{0, 0};
  // Each block's two corners on the other's face, 5 mm off.
  const ContactCandidates first = search(s, polygons, fixed);
  EXPECT_EQ(first.size(), 4u);
  expect_same(search(s, polygons, fixed), first, 0);
  EXPECT_EQ(s.list_count(), 1);
  s.forget();
  expect_same(search(s, polygons, fixed), first, 1);
  EXPECT_EQ(s.list_count(), 2);
}

}  // namespace
}  // namespace hydrodda::dda
