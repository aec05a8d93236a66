// The step control of a coupled transient run (run/coupled_transient.hpp): steps grow by 1.2
// when they came in few iterations, land on the output times and the end, and are cut down to a
// floor of the first step over 2^10. Plain arithmetic: exact.

#include <gtest/gtest.h>

#include "run/coupled_transient.hpp"

namespace hydrodda::run {
namespace {

scenario::Scenario transient_scenario() {
  scenario::Scenario s;
  s.flow.emplace();
  s.flow->transient.emplace();
  s.flow->transient->end_time = 100.0;
  s.flow->transient->time_step = 1.0;
  s.flow->transient->max_time_step = 10.0;
  s.flow->transient->output_times = {30.0, 0.0, 30.0, 100.0, 50.0};
  s.coupling.max_iterations = 40;
  return s;
}

TEST(CoupledTransientSteps, StepsGrowWhenFewIterationsAreNeededUpToTheLargest) {
  const StepControl control = make_step_control(transient_scenario());
  EXPECT_EQ(control.few_iterations, 10);  // a quarter of coupling.max_iterations
  EXPECT_DOUBLE_EQ(control.floor, 1.0 / 1024.0);
  EXPECT_DOUBLE_EQ(grow_step(control, 2.0, 10), 2.4);
  EXPECT_DOUBLE_EQ(grow_step(control, 2.0, 11), 2.0);  // more than few: kept
  EXPECT_DOUBLE_EQ(grow_step(control, 9.0, 3), 10.0);  // up to max_time_step
}

TEST(CoupledTransientSteps, StepsLandOnTheOutputTimesAndTheEnd) {
  EXPECT_EQ(find_step_stops(transient_scenario()), (std::vector<double>{30.0, 50.0, 100.0}));
  EXPECT_DOUBLE_EQ(land_on_stop(25.0, 10.0, 30.0), 5.0);
  EXPECT_DOUBLE_EQ(land_on_stop(20.0, 10.0 - 1e-7, 30.0), 10.0);  // no sliver left
  EXPECT_DOUBLE_EQ(land_on_stop(10.0, 10.0, 30.0), 10.0);
}

}  // namespace
}  // namespace hydrodda::run
