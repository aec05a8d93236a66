// The coupled transient stepper's ends (run/coupled_transient_stepper.hpp) on the jacked block
// whose head rises slowly through H* (tests/cli/scenarios/jacking_ramp_in_time.toml): its step 9,
// cut to the floor, throws the block in a later iteration, and steady passes from step 8's end
// ask whether its load has any equilibrium (run/no_equilibrium_in_time.hpp).

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "coupling/staggered_loop.hpp"
#include "run/coupled_model.hpp"
#include "run/coupled_transient_stepper.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::run {
namespace {

namespace fs = std::filesystem;

const fs::path kRamp = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/jacking_ramp_in_time.toml";

// Steps with no stop request until a step does not step; the steps taken.
int step_until_one_fails(CoupledTransientStepper& stepper) {
  const std::function<bool()> never = [] { return false; };
  int taken = 0;
  while (stepper.step(never) == CoupledTransientStepper::Outcome::stepped) ++taken;
  return taken;
}

// Unstopped, step 9 fails with no equilibrium, named by the steady passes. A stop requested at
// the first of those steady passes (the first pass asked outside a time step's iterations)
// answers nothing: the step ends interrupted, the stepper at step 8's end and not failed, as a
// stop within the step's own iterations ends it (without this, the steady passes ignored the
// stop request and the step ended failed).
TEST(CoupledTransientStepper, AStopDuringTheSteadyPassesOfAFailedStepEndsItInterrupted) {
  const scenario::Scenario s = scenario::read_scenario(kRamp);

  CoupledModel unstopped(s);
  unstopped.start_in_time();
  CoupledTransientStepper through(unstopped);
  const int held = step_until_one_fails(through);
  ASSERT_EQ(held, 8);
  ASSERT_TRUE(through.failed());
  ASSERT_GT(through.failed_step().steady_pass, 0);
  ASSERT_FALSE(through.failed_step().escaped.empty());

  CoupledModel model(s);
  model.start_in_time();
  CoupledTransientStepper stepper(model);
  const std::function<bool()> never = [] { return false; };
  for (int k = 0; k < held; ++k) ASSERT_EQ(stepper.step(never), CoupledTransientStepper::Outcome::stepped);
  const double time_held = stepper.time();
  int asked_outside_time_step = 0;
  const std::function<bool()> stop_at_steady_passes = [&] {
    if (model.loop().in_time_step()) return false;
    ++asked_outside_time_step;
    return true;
  };
  EXPECT_EQ(stepper.step(stop_at_steady_passes), CoupledTransientStepper::Outcome::interrupted);
  EXPECT_EQ(asked_outside_time_step, 1);
  EXPECT_FALSE(stepper.failed());
  EXPECT_EQ(stepper.steps(), held);
  EXPECT_EQ(stepper.time(), time_held);
}

}  // namespace
}  // namespace hydrodda::run
