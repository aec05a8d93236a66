// How long the blocks a static step moves freely take to come to rest on something
// (dda/free_drift.cpp: StepReport::free_drift_steps, System::free_drift()), against exact
// identities. A static step from rest moves a body that nothing holds by F Δt²/2M (Shi 1988,
// §2.4; UnbalancedForce.AFreeBodyIsWhollyUnbalancedAtAnyTimeStep), a translation its
// linearised penetrations follow exactly, so the landing times below hold to round-off:
// tolerance 1e-9 of them.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dda/system.hpp"
#include "test_models.hpp"

namespace hydrodda::dda {
namespace {

using testing::make_rectangle;

constexpr double kGravity = 9.81;
constexpr double kStep = 1e-3;
constexpr double kFall = 0.5 * kGravity * kStep * kStep;  // a free body's fall in a static step
constexpr double kNever = std::numeric_limits<double>::infinity();

// A 2 m × 1 m block (ρ 2500) `gap` above a fixed 4 m × 1 m base in a static analysis under
// gravity; with `base = false` the base is left out and nothing lies below it.
ModelDefinition make_block_over_base(double gap, bool base) {
  ModelDefinition m;
  m.materials = {Material{2500.0, 1.0e10, 0.25}};
  if (base) m.blocks.push_back({make_rectangle(-1, -1, 3, 0), 0, true});
  m.blocks.push_back({make_rectangle(0, gap, 2, 1 + gap), 0, false});
  m.joint = {30.0, 0.0, 0.0};
  m.settings.analysis = Analysis::static_;
  m.settings.time_step = kStep;
  return m;
}

// A second 2 m × 1 m block `gap` above the first, pushed up at its centroid by `lift` times
// its weight (5,000 kg a metre): it falls by (1 − lift) kFall a step.
void add_block_above(ModelDefinition& m, double gap, double lift) {
  const double bottom = m.blocks.back().polygon[2].y + gap;
  m.blocks.push_back({make_rectangle(0, bottom, 2, bottom + 1), 0, false});
  const int block = static_cast<int>(m.blocks.size()) - 1;
  m.point_loads.push_back({block, {1.0, bottom + 0.5}, constant_force({0.0, lift * 5000.0 * kGravity})});
}

// After the first step the block's bottom corners are g − δ above the base and close by δ a
// step: it meets the base in (g − δ)/δ steps, and lands then: its contacts close within a
// step of that and the block is held (no free block: 0 and −1). The base is at rest: 0.
TEST(FreeDrift, ABlockFallingOnABaseMeetsItInItsGapOverItsStep) {
  const double gap = 1e-3;
  System system(make_block_over_base(gap, true));
  const StepReport first = system.step();
  ASSERT_NEAR(first.max_displacement, kFall, 1e-9 * kFall);
  const double expected = (gap - kFall) / kFall;
  EXPECT_NEAR(first.free_drift_steps, expected, 1e-9 * expected);
  EXPECT_EQ(first.free_drift_block, 1);
  EXPECT_EQ(first.block_meeting_nothing, -1);
  EXPECT_EQ(system.free_drift().landing_steps[0], 0.0);
  EXPECT_NEAR(system.free_drift().motion[1], kFall, 1e-9 * kFall);
  int steps = 1;
  StepReport step = first;
  while (step.free_drift_block >= 0 && steps < 1000) {
    step = system.step();
    ++steps;
  }
  EXPECT_LE(std::abs(steps - (1.0 + expected)), 2.0) << "landed after " << steps << " steps";
  EXPECT_EQ(step.free_drift_steps, 0.0);
  EXPECT_EQ(system.free_drift().landing_steps[1], 0.0);
}

// Nothing below: the falling block meets nothing (∞ steps), and the step names it: whether it
// escapes is the coupled loop's to judge.
TEST(FreeDrift, ABlockFallingWithNothingBelowMeetsNothing) {
  System system(make_block_over_base(1e-3, false));
  const StepReport step = system.step();
  EXPECT_GT(step.max_displacement, 0.0);
  EXPECT_EQ(step.free_drift_steps, 0.0);
  EXPECT_EQ(step.free_drift_block, -1);
  EXPECT_EQ(step.block_meeting_nothing, 0);
  EXPECT_EQ(system.free_drift().landing_steps[0], kNever);
}

// Two blocks falling together onto the base, the upper 1 mm over the lower: the joint between
// them closes by nothing (both move δ), so the upper lands 1 mm ÷ δ steps after the lower:
// (g − δ)/δ + 1 mm/δ. A stack of free blocks in open joints lands a row at a time.
TEST(FreeDrift, ABlockFallingWithTheOneUnderItLandsAfterIt) {
  const double gap = 1e-3;
  ModelDefinition m = make_block_over_base(gap, true);
  add_block_above(m, gap, 0.0);
  System system(std::move(m));
  const StepReport step = system.step();
  const double lower = (gap - kFall) / kFall;
  const double expected = lower + gap / kFall;
  EXPECT_NEAR(system.free_drift().landing_steps[1], lower, 1e-9 * lower);
  EXPECT_NEAR(step.free_drift_steps, expected, 1e-9 * expected);
  EXPECT_EQ(step.free_drift_block, 2);
}

// The upper block held up by half its weight falls δ/2 a step: the joint opens by δ/2 a step
// until the lower lands at T_l = (g − δ)/δ, then the upper closes what is left of it alone:
// T_u = T_l + (g + δ/2 + (δ/2) T_l)/(δ/2), its gap after the first step g + δ/2.
TEST(FreeDrift, ABlockFallingSlowerThanTheOneUnderItLandsWhenItHasClosedTheGapLeft) {
  const double gap = 1e-3;
  ModelDefinition m = make_block_over_base(gap, true);
  add_block_above(m, gap, 0.5);
  System system(std::move(m));
  const StepReport step = system.step();
  const double lower = (gap - kFall) / kFall;
  const double half = 0.5 * kFall;
  const double expected = lower + (gap + half + half * lower) / half;
  EXPECT_NEAR(step.free_drift_steps, expected, 1e-9 * expected);
  EXPECT_EQ(step.free_drift_block, 2);
}

// The upper block pushed up by twice its weight rises off the lower, which falls onto the base:
// the upper moves away from the one it would land behind and meets nothing, as the part of a
// column lifted past the critical gradient does off a block that falls back.
TEST(FreeDrift, ABlockRisingOffTheOneUnderItMeetsNothing) {
  const double gap = 1e-3;
  ModelDefinition m = make_block_over_base(gap, true);
  add_block_above(m, gap, 2.0);
  System system(std::move(m));
  const StepReport step = system.step();
  const double lower = (gap - kFall) / kFall;
  EXPECT_NEAR(step.free_drift_steps, lower, 1e-9 * lower);
  EXPECT_EQ(step.free_drift_block, 1);
  EXPECT_EQ(step.block_meeting_nothing, 2);
  EXPECT_EQ(system.free_drift().landing_steps[2], kNever);
}

// Blocks held together by a closed contact move as one: the upper pressed onto the lower (a
// load of its weight down on it) closes their joint, and the pair falls with nothing below.
// Held, but by nothing at rest: both meet nothing.
TEST(FreeDrift, BlocksHeldTogetherFallingWithNothingBelowMeetNothing) {
  ModelDefinition m = make_block_over_base(0.0, false);
  add_block_above(m, 0.0, -1.0);
  System system(std::move(m));
  StepReport step;
  for (int k = 0; k < 5; ++k) step = system.step();
  ASSERT_GT(step.contacts, 0) << "the pressed joint must be closed";
  EXPECT_EQ(step.free_drift_block, -1);
  EXPECT_EQ(system.free_drift().landing_steps[0], kNever);
  EXPECT_EQ(system.free_drift().landing_steps[1], kNever);
}

// A block resting on its base: its contacts closed to a fixed block, it is at rest (0), and
// no block moves freely.
TEST(FreeDrift, ABlockOnItsBaseIsHeld) {
  System system(make_block_over_base(0.0, true));
  StepReport step;
  for (int k = 0; k < 5; ++k) step = system.step();
  EXPECT_EQ(step.free_drift_steps, 0.0);
  EXPECT_EQ(step.free_drift_block, -1);
  EXPECT_EQ(step.block_meeting_nothing, -1);
  EXPECT_EQ(system.free_drift().landing_steps[1], 0.0);
}

}  // namespace
}  // namespace hydrodda::dda
