// When a settling pass may stop before its blocks are at rest (coupling/settling_watch.hpp),
// on made-up steps: each block's displacement in a step and the steps it takes to land.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coupling/settling_watch.hpp"

namespace hydrodda::coupling {
namespace {

constexpr double kNever = dda::FreeDrift::kNever;
constexpr int kInARow = 20;
constexpr double kAtRest = 1e-7;

dda::FreeDrift drift(std::vector<double> motion, std::vector<double> landing) {
  return {std::move(motion), std::move(landing)};
}

// A motion that falls by r a step, u_k = u_0 r^k, is under `at_rest` from the step
// k = ln(at_rest/u_0)/ln r on. From u_1 = r (u_0 = 1, r = ½) with at_rest = 1.01 × 2⁻¹⁰ it
// takes 9 − log₂ 1.01 = 8.986 more steps: in time with 9 left, not with 8.
TEST(SettlingWatch, ASlowingBlockComesToRestWhereItsMotionFallsUnderTheLimit) {
  const double at_rest = 1.01 * std::pow(2.0, -10);
  EXPECT_TRUE(SettlingWatch::slows_to_rest(1.0, 0.5, at_rest, 9));
  EXPECT_FALSE(SettlingWatch::slows_to_rest(1.0, 0.5, at_rest, 8));
  EXPECT_FALSE(SettlingWatch::slows_to_rest(1.0, 1.0, at_rest, 1000000)) << "a steady block never rests";
  EXPECT_FALSE(SettlingWatch::slows_to_rest(1.0, 1.1, at_rest, 1000000)) << "nor one speeding up";
  EXPECT_TRUE(SettlingWatch::slows_to_rest(1.0, 0.5 * at_rest, at_rest, 0)) << "one under the limit is at rest";
}

// A block falling steadily (2.8 µm a step) that lands 1,000 steps on, with 500 left and fewer
// each step: every step drifts, and the pass may stop after `in_a_row` of them, naming it.
TEST(SettlingWatch, ASteadilyFallingBlockEndsThePassAfterItsStepsInARow) {
  SettlingWatch watch(kInARow, kAtRest);
  for (int k = 0; k < kInARow; ++k) {
    EXPECT_FALSE(watch.cannot_come_to_rest()) << "after " << k << " steps";
    watch.observe(drift({0.0, 2.8e-6}, {0.0, 1000.0 - k}), 500 - k);
    EXPECT_EQ(watch.drifting_block(), 1);
  }
  EXPECT_TRUE(watch.cannot_come_to_rest());
}

// The same block halving its motion each step (a float, a balance of loads): from its second
// step on it comes to rest in time, wherever its rate would land it, and the pass steps on.
TEST(SettlingWatch, ASlowingBlockKeepsThePassStepping) {
  SettlingWatch watch(kInARow, kAtRest);
  double motion = 2.8e-6;
  for (int k = 0; k < 3 * kInARow && motion > kAtRest; ++k, motion *= 0.5) {
    watch.observe(drift({0.0, motion}, {0.0, 1000.0 + k}), 500 - k);
    if (k > 0) EXPECT_EQ(watch.drifting_block(), -1) << "step " << k;
  }
  EXPECT_FALSE(watch.cannot_come_to_rest());
}

// Slowing by 10⁻⁶ a step, 2.8 µm takes some 3.3 million steps to fall under 0.1 µm: not within
// the 500 left, so the block drifts and the pass may stop.
TEST(SettlingWatch, ABlockSlowingTooLittleToRestInTimeDrifts) {
  SettlingWatch watch(kInARow, kAtRest);
  double motion = 2.8e-6;
  for (int k = 0; k < kInARow; ++k, motion *= 1.0 - 1e-6) watch.observe(drift({0.0, motion}, {0.0, 1000.0}), 500 - k);
  EXPECT_TRUE(watch.cannot_come_to_rest());
}

// Beside the falling block, one that rises steadily and meets nothing (a column lifted past the
// critical gradient, a jacked block): no step drifts, as only stepping on shows where it goes.
// Once it slows into a rest, the falling block alone decides.
TEST(SettlingWatch, ABlockMeetingNothingKeepsThePassSteppingUnlessItSlowsIntoARest) {
  SettlingWatch steady(kInARow, kAtRest);
  for (int k = 0; k < 3 * kInARow; ++k) steady.observe(drift({2.8e-6, 5e-6}, {1000.0, kNever}), 500 - k);
  EXPECT_FALSE(steady.cannot_come_to_rest());
  EXPECT_EQ(steady.drifting_block(), -1);
  SettlingWatch slowing(kInARow, kAtRest);
  double motion = 5e-6;
  for (int k = 0; k <= kInARow; ++k, motion *= 0.5) slowing.observe(drift({2.8e-6, motion}, {1000.0, kNever}), 500 - k);
  EXPECT_TRUE(slowing.cannot_come_to_rest());
  EXPECT_EQ(slowing.drifting_block(), 0);
}

// A block that lands within the steps left, and blocks at rest (0 steps), keep it stepping.
TEST(SettlingWatch, BlocksLandingInTimeKeepThePassStepping) {
  SettlingWatch watch(kInARow, kAtRest);
  for (int k = 0; k < 3 * kInARow; ++k) watch.observe(drift({0.0, 2.8e-6}, {0.0, 400.0 - k}), 500 - k);
  EXPECT_FALSE(watch.cannot_come_to_rest());
  EXPECT_EQ(watch.drifting_block(), -1);
}

// A step that does not drift breaks the row: the pass stops only after `in_a_row` more.
TEST(SettlingWatch, AStepThatDoesNotDriftStartsTheRowAgain) {
  SettlingWatch watch(kInARow, kAtRest);
  for (int k = 0; k < kInARow - 1; ++k) watch.observe(drift({2.8e-6}, {1000.0}), 500 - k);
  watch.observe(drift({2.8e-6}, {100.0}), 480);
  EXPECT_EQ(watch.drifting_steps(), 0);
  for (int k = 0; k < kInARow - 1; ++k) watch.observe(drift({2.8e-6}, {1000.0}), 479 - k);
  EXPECT_FALSE(watch.cannot_come_to_rest());
  watch.observe(drift({2.8e-6}, {1000.0}), 460);
  EXPECT_TRUE(watch.cannot_come_to_rest());
}

}  // namespace
}  // namespace hydrodda::coupling
