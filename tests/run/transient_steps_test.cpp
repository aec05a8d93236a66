// The plan of a transient run's steps (run/transient_flow.hpp): the first is time_step, each
// later one kTimeStepGrowth times the last up to max_time_step, and a step that would pass an
// output time or the end ends there exactly. Exact identities: the times are compared with ==.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "run/transient_flow.hpp"

namespace hydrodda::run {
namespace {

scenario::TransientDefinition transient(double end, double first, double largest, std::vector<double> outputs) {
  scenario::TransientDefinition t;
  t.end_time = end;
  t.time_step = first;
  t.max_time_step = largest;
  t.output_times = std::move(outputs);
  return t;
}

TEST(TransientSteps, GrowFromTheFirstStepToTheLargestAndEndOnTheEndTime) {
  const std::vector<double> times = plan_step_times(transient(100.0, 1.0, 10.0, {100.0}));
  ASSERT_GE(times.size(), 3u);
  EXPECT_EQ(times[0], 1.0);
  EXPECT_EQ(times[1], 1.0 + 1.0 * kTimeStepGrowth);
  EXPECT_EQ(times.back(), 100.0);
  double previous_step = 1.0, t = 1.0;
  for (std::size_t n = 1; n + 1 < times.size(); ++n) {
    const double step = times[n] - t;
    EXPECT_NEAR(step, std::min(previous_step * kTimeStepGrowth, 10.0), 1e-12 * times[n]) << n;
    previous_step = step;
    t = times[n];
  }
  EXPECT_LE(times.back() - t, 10.0);
}

TEST(TransientSteps, EndExactlyOnEachOutputTimeAndGrowOnAfterIt) {
  const std::vector<double> outputs{0.0, 2.5, 7.0, 50.0};
  const std::vector<double> times = plan_step_times(transient(50.0, 1.0, 4.0, outputs));
  for (double t : outputs)
    if (t > 0.0) EXPECT_NE(std::find(times.begin(), times.end(), t), times.end()) << t;
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
  EXPECT_EQ(std::adjacent_find(times.begin(), times.end()), times.end());  // strictly increasing
  // 1, then 2.2 would be 2.2 < 2.5: taken; the next, 1.44 long, would pass 2.5: ends there.
  EXPECT_EQ(times[0], 1.0);
  EXPECT_EQ(times[2], 2.5);
  // After it the nominal step grows on from its own length (1.728), not from the 0.3 s cut.
  EXPECT_NEAR(times[3] - times[2], 1.0 * std::pow(kTimeStepGrowth, 3), 1e-12);
}

TEST(TransientSteps, EndOnTheBoundaryTablesRowsToo) {
  const std::vector<double> times = plan_step_times(transient(20.0, 1.0, 4.0, {20.0}), {0.0, 3.3, 11.0, 30.0});
  for (double t : {3.3, 11.0, 20.0}) EXPECT_NE(std::find(times.begin(), times.end(), t), times.end()) << t;
  EXPECT_EQ(times.back(), 20.0);  // a row past the end is not stepped to
  EXPECT_EQ(std::adjacent_find(times.begin(), times.end()), times.end());
}

TEST(TransientSteps, ARunOfOneStep) {
  EXPECT_EQ(plan_step_times(transient(5.0, 5.0, 5.0, {5.0})), std::vector<double>{5.0});
}

}  // namespace
}  // namespace hydrodda::run
