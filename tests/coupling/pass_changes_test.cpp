// What changed across a coupling pass (coupling/pass_changes.hpp): contacts whose state
// changed, joint crossings that switched between open and closed, the fluid load's change.
// Exact counts on hand-built lists; the load change to 1e-15 of the hand value.

#include <gtest/gtest.h>

#include <vector>

#include "coupling/pass_changes.hpp"

namespace hydrodda::coupling {
namespace {

using dda::ContactInfo;
using dda::ContactKey;
using dda::ContactState;

ContactInfo contact(int block_i, int vertex, ContactState state) { return {ContactKey{block_i, vertex, 1, 0}, state}; }

TEST(PassChanges, CountsContactsWhoseStateChanged) {
  const std::vector<ContactInfo> before{contact(0, 0, ContactState::locked), contact(0, 1, ContactState::open),
                                        contact(0, 2, ContactState::sliding), contact(2, 0, ContactState::locked)};
  const std::vector<ContactInfo> after{contact(0, 0, ContactState::locked), contact(0, 1, ContactState::locked),
                                       contact(0, 2, ContactState::locked), contact(2, 0, ContactState::locked)};
  // (0, 1) closed, (0, 2) stopped sliding: 2.
  EXPECT_EQ(count_contact_state_changes(before, after), 2);
  EXPECT_EQ(count_contact_state_changes(after, before), 2);
  EXPECT_EQ(count_contact_state_changes(before, before), 0);
}

TEST(PassChanges, AContactThatAppearsOrGoesCountsOnlyWhenClosed) {
  const std::vector<ContactInfo> before{contact(0, 0, ContactState::open), contact(1, 0, ContactState::locked)};
  const std::vector<ContactInfo> after{contact(0, 3, ContactState::open), contact(3, 0, ContactState::sliding)};
  // (0, 0) open went, (0, 3) open came: nothing; (1, 0) locked went, (3, 0) sliding came: 2.
  EXPECT_EQ(count_contact_state_changes(before, after), 2);
  EXPECT_EQ(count_contact_state_changes({}, after), 1);
  EXPECT_EQ(count_contact_state_changes(before, {}), 1);
}

TEST(PassChanges, CountsCrossingsThatSwitchedBetweenOpenAndClosed) {
  const double open_above = 6e-5;  // a_r + V_m
  const std::vector<double> before{1e-5, 6e-5, 7e-5, 8e-5, 2e-5};
  const std::vector<double> after{1.5e-5, 6.1e-5, 5e-5, 9e-5, 2e-5};
  // Crossing 1 opened (6e-5 is not above), crossing 2 closed: 2.
  EXPECT_EQ(count_switched(before, after, open_above), 2);
  EXPECT_EQ(count_switched(before, before, open_above), 0);
  EXPECT_EQ(count_switched({}, after, open_above), 0) << "no pass before: nothing to compare";
  // Each crossing by its own type's a_r + V_m: crossing 4 is of a type with a(0) = 1.5e-5, so its
  // 2e-5 is open in both passes; crossing 0 (1e-5 → 1.5e-5) of a type with a(0) = 1.2e-5 opened.
  const std::vector<double> own{1.2e-5, 6e-5, 6e-5, 6e-5, 1.5e-5};
  EXPECT_EQ(count_switched(before, after, own), 3);
  EXPECT_EQ(count_switched(before, after, std::vector<double>(5, open_above)), 2);
  EXPECT_EQ(count_switched({}, after, own), 0);
}

TEST(PassChanges, TheLoadChangeIsTheLargestVertexChangeOverTheLargestForce) {
  const std::vector<std::vector<geometry::Point>> previous{{{0.0, 10.0}, {0.0, 10.0}}, {{3.0, 0.0}}};
  const std::vector<std::vector<geometry::Point>> current{{{0.0, 12.0}, {0.0, 10.0}}, {{0.0, 4.0}}};
  // Changes 2 and |(−3, 4)| = 5; largest force 12: 5/12.
  EXPECT_NEAR(relative_load_change(current, previous), 5.0 / 12.0, 1e-15);
  EXPECT_EQ(relative_load_change(current, current), 0.0);
  EXPECT_EQ(relative_load_change(current, {}), 1.0) << "no pass before";
  EXPECT_EQ(relative_load_change({{{0.0, 0.0}}}, {{{0.0, 0.0}}}), 0.0);
}

}  // namespace
}  // namespace hydrodda::coupling
