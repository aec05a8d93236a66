// The secant that moves a block group meeting nothing to where its net load vanishes
// (coupling/float_secant.hpp), on made-up passes of a free body: under a net load
// N(x) = K (x* − x) held through a pass of steps whose Σ Δt² is S, a static DDA step moves a
// body of mass M by N Δt²/2M, so the pass takes it from x to x + N(x) S/2M.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "coupling/float_secant.hpp"

namespace hydrodda::coupling {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One pass of a free body of mass M under N(x) = K (x* − x) along y.
struct LinearFloat {
  double stiffness = 2.5e4;  // K (N/m per m of width): ρ_w g (1 + i) of the lifted column
  double mass = 2.5e4;       // M (kg per m of width)
  double rest = 0.279;       // x*
  double squared_steps = 2020 * 1e-4;  // S = 2,020 steps of 0.01 s
  double end_of_pass(double x) const { return x + stiffness * (rest - x) * squared_steps / (2.0 * mass); }
};

// For a load linear in x the secant is exact: after two plain passes the shift lands the
// group on x* to round-off, K/2M and x* known from nowhere else.
TEST(FloatSecant, ALoadLinearInThePositionIsZeroedByTheSecantInOneShift) {
  const LinearFloat body;
  FloatSecant secant;
  const std::vector<int> group{1, 2, 3};
  const double x0 = 0.0, x1 = body.end_of_pass(x0);
  EXPECT_EQ(secant.shift(group, {0, x0}, {0, x1}, x1 - x0, body.squared_steps, 1.0).y, 0.0)
      << "one pass gives no secant";
  const double x2 = body.end_of_pass(x1);
  const Point shift = secant.shift(group, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 1.0);
  EXPECT_NEAR(x2 + shift.y, body.rest, 1e-12);
  EXPECT_EQ(shift.x, 0.0);
}

// The same with the pass's steps cut (a smaller Σ Δt² in the second pass): the rate per
// step² is what the secant pairs, so the root does not move.
TEST(FloatSecant, APassOfFewerOrShorterStepsGivesTheSameRoot) {
  LinearFloat body;
  FloatSecant secant;
  const std::vector<int> group{4};
  const double x1 = body.end_of_pass(0.05);
  secant.shift(group, {0, 0.05}, {0, x1}, x1 - 0.05, body.squared_steps, 1.0);
  body.squared_steps *= 0.3;
  const double x2 = body.end_of_pass(x1);
  const Point shift = secant.shift(group, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 1.0);
  EXPECT_NEAR(x2 + shift.y, body.rest, 1e-12);
}

// A load that does not fall as the group moves (a jacked block whose joint keeps its
// pressure) has no equilibrium ahead: no shift, the group steps on; nor does one whose float
// lies more than a thousand passes' motion ahead.
TEST(FloatSecant, ALoadThatDoesNotFallAsTheGroupMovesGivesNoShift) {
  FloatSecant secant;
  const std::vector<int> group{1};
  secant.shift(group, {0, 0.0}, {0, 0.01}, 0.01, 0.2, 1.0);
  EXPECT_EQ(secant.shift(group, {0, 0.01}, {0, 0.02}, 0.01, 0.2, 1.0).y, 0.0) << "constant load";
  EXPECT_EQ(secant.shift(group, {0, 0.02}, {0, 0.04}, 0.02, 0.2, 1.0).y, 0.0) << "a load that grows";
  // One that falls so slowly that a pass closes under a thousandth of the way to its float
  // (K S/2M = 0.9e-3, the float 0.279 m off): the group steps on.
  LinearFloat slow;
  slow.squared_steps = 0.9e-3 * 2.0 * slow.mass / slow.stiffness;
  FloatSecant again;
  const double x1 = slow.end_of_pass(0.0), x2 = slow.end_of_pass(x1);
  again.shift(group, {0, 0.0}, {0, x1}, x1, slow.squared_steps, 1.0);
  EXPECT_EQ(again.shift(group, {0, x1}, {0, x2}, x2 - x1, slow.squared_steps, 1.0).y, 0.0) << "too slow a fall";
  // At 1.1e-3 it is moved.
  slow.squared_steps = 1.1e-3 * 2.0 * slow.mass / slow.stiffness;
  FloatSecant third;
  const double y1 = slow.end_of_pass(0.0), y2 = slow.end_of_pass(y1);
  third.shift(group, {0, 0.0}, {0, y1}, y1, slow.squared_steps, 1.0);
  EXPECT_NEAR(y2 + third.shift(group, {0, y1}, {0, y2}, y2 - y1, slow.squared_steps, 1.0).y, slow.rest, 1e-9);
}

// The shift is at most the DDA's allowed step displacement, along the secant's direction.
TEST(FloatSecant, TheShiftIsCappedAtTheLengthGiven) {
  const LinearFloat body;
  FloatSecant secant;
  const std::vector<int> group{1};
  const double x1 = body.end_of_pass(0.0), x2 = body.end_of_pass(x1);
  secant.shift(group, {0, 0.0}, {0, x1}, x1, body.squared_steps, 0.05);
  EXPECT_NEAR(secant.shift(group, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 0.05).y, 0.05, 1e-15);
}

// A pass that overshoots the rest (K S/2M = 1.5: x − x* times −0.5 a pass) has the secant
// take the group back, but no block of it farther back than it advanced in the pass (space it
// crossed free): the exact root is 0.02 back, the slowest block advanced 0.005.
TEST(FloatSecant, AGroupGoesBackNoFartherThanItsSlowestBlockAdvanced) {
  LinearFloat body;
  body.rest = 0.0;
  body.squared_steps = 1.5 * 2.0 * body.mass / body.stiffness;
  const std::vector<int> group{1, 2};
  const double x1 = body.end_of_pass(0.08), x2 = body.end_of_pass(x1);  // −0.04, 0.02
  for (const double slowest : {0.06, 0.005}) {
    FloatSecant secant;
    secant.shift(group, {0, 0.08}, {0, x1}, 0.12, body.squared_steps, 1.0);
    const Point shift = secant.shift(group, {0, x1}, {0, x2}, slowest, body.squared_steps, 1.0);
    EXPECT_NEAR(shift.y, slowest == 0.06 ? -0.02 : -0.005, 1e-15) << slowest;
  }
}

// Passes in a row only: a group not free in a pass is forgotten, and one whose blocks changed
// is another group.
TEST(FloatSecant, OnlyTheSameGroupInTheNextPassIsPaired) {
  const LinearFloat body;
  FloatSecant secant;
  const double x1 = body.end_of_pass(0.0), x2 = body.end_of_pass(x1);
  secant.shift({1, 2}, {0, 0.0}, {0, x1}, x1, body.squared_steps, 1.0);
  EXPECT_EQ(secant.shift({1, 2, 3}, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 1.0).y, 0.0);
  secant.keep_only({});
  EXPECT_EQ(secant.shift({1, 2, 3}, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 1.0).y, 0.0);
}

// The groups: blocks meeting nothing (landing steps infinite), joined by any contact among
// them; a contact with a block that lands or rests joins nothing.
// What a checkpoint keeps of the secant (remembered) and a resumed run takes up (restore): a
// secant restored from it gives the next pass the shift the one that went on gives, bit for
// bit; a group that names no block of the system is refused.
TEST(FloatSecant, ASecantRestoredFromWhatItRememberedShiftsAsTheOneThatWentOn) {
  const LinearFloat body;
  FloatSecant secant;
  const std::vector<int> group{1, 2, 3};
  const double x0 = 0.0, x1 = body.end_of_pass(x0), x2 = body.end_of_pass(x1);
  secant.shift(group, {0, x0}, {0, x1}, x1 - x0, body.squared_steps, 1.0);
  FloatSecant restored;
  restored.restore(secant.remembered(), 4);
  const Point went_on = secant.shift(group, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 1.0);
  const Point resumed = restored.shift(group, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 1.0);
  ASSERT_NE(went_on.y, 0.0) << "the second pass is paired with the first";
  EXPECT_EQ(resumed.x, went_on.x);
  EXPECT_EQ(resumed.y, went_on.y);
  EXPECT_EQ(FloatSecant{}.shift(group, {0, x1}, {0, x2}, x2 - x1, body.squared_steps, 1.0).y, 0.0)
      << "a secant that forgot gives none";
  EXPECT_THROW(restored.restore({{{1, 4}, {0, 0}, {0, 0}}}, 4), std::invalid_argument) << "block 4 of 4";
  EXPECT_THROW(restored.restore({{{2, 1}, {0, 0}, {0, 0}}}, 4), std::invalid_argument) << "not ascending";
  EXPECT_THROW(restored.restore({{{}, {0, 0}, {0, 0}}}, 4), std::invalid_argument) << "empty";
}

TEST(FloatSecant, FreeBlocksJoinedByAnyContactAreOneGroup) {
  const std::vector<double> landing{0.0, kInf, kInf, kInf, 12.0, kInf};
  std::vector<dda::ContactInfo> contacts(4);
  contacts[0].key = {1, 0, 2, 0};
  contacts[0].state = dda::ContactState::locked;
  contacts[1].key = {3, 0, 2, 1};  // open: a gap between them
  contacts[2].key = {0, 0, 1, 2};  // with the base at rest
  contacts[2].state = dda::ContactState::locked;
  contacts[3].key = {5, 0, 4, 0};  // with a block that lands
  contacts[3].state = dda::ContactState::sliding;
  const std::vector<std::vector<int>> groups = find_free_groups(landing, contacts);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(groups[1], (std::vector<int>{5}));
}

}  // namespace
}  // namespace hydrodda::coupling
