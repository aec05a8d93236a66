// Loads over time through the real program (docs/scenario.md, "Loads over time"). Reference:
// identities. Steady flow keeps no memory of its path, so a flow-only run whose head is a table
// ends exactly where the run at its last value does. A coupled run goes through its load steps,
// each converged before the next; elastic blocks held at fixed points end where the run under
// the last loads alone ends, to the coupling tolerance and the order of the blocks' strain
// (DDA adds each step's stress on that step's geometry, so two paths to one load differ by
// about the strain, 4e-4 here, relative).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupled_runs.hpp"

using namespace hydrodda::testing::coupled;

namespace {

TEST(LoadSteps, AFlowOnlyRunEndsAtItsTablesLastValueExactly) {
  const std::string text = read_text(kVerification / "flow_linear_head.toml");
  int count = 0;
  const std::string table = replace_all(text, "head = 3.0", "head = [[0.0, 2.0], [10.0, 5.0], [20.0, 3.0]]", count);
  ASSERT_EQ(count, 1);
  const RunResult stepped = run_text_and_read(table, "load-steps-flow-table");
  const RunResult constant = run_and_read(kVerification / "flow_linear_head.toml", "load-steps-flow-constant");
  ASSERT_TRUE(stepped.summary.contains("flow"));
  EXPECT_EQ(stepped.summary["flow"]["boundaries"], constant.summary["flow"]["boundaries"]);  // bit for bit
  EXPECT_EQ(stepped.summary["converged"], true);
}

// The closed joint under uniform pore pressure at Biot's α = 0 (pressurised_joint_test.cpp):
// the pressure on every side stepped from 5 to 10 MPa against 10 MPa from the start.
TEST(LoadSteps, ACoupledRunConvergesAtEachLoadStepAndEndsAsTheRunAtItsLastLoads) {
  const std::string text = read_text(kVerification / "coupled_pressurised_joint.toml");
  int count = 0;
  std::string constant = replace_all(text, "biot_coefficient = 1.0", "biot_coefficient = 0.0", count);
  ASSERT_EQ(count, 1);
  constant = replace_all(constant, "max_iterations = 5", "max_iterations = 20", count);
  ASSERT_EQ(count, 1);
  const std::string table = replace_all(constant, "pressure = 1.0e7", "pressure = [[0.0, 5.0e6], [1.0, 1.0e7]]", count);
  ASSERT_EQ(count, 4);  // every side
  const RunResult stepped = run_text_and_read(table, "load-steps-coupled-table");
  const RunResult direct = run_text_and_read(constant, "load-steps-coupled-constant");
  EXPECT_EQ(stepped.summary["converged"], true);
  EXPECT_EQ(direct.summary["converged"], true);

  // One history row a pass, each with its load step and time; the last pass of each step
  // converged (both changes under the tolerance, 1e-4).
  ASSERT_GE(stepped.history.size(), 3u);
  const int step = column_of(stepped.history[0], "load_step"), time = column_of(stepped.history[0], "load_time");
  const int head = column_of(stepped.history[0], "head_change"), moved = column_of(stepped.history[0], "displacement_change");
  ASSERT_GE(step, 0);
  ASSERT_GE(time, 0);
  EXPECT_EQ(column_of(direct.history[0], "load_step"), -1);  // no column where every load is a constant
  int steps_seen = 0;
  for (std::size_t row = 1; row < stepped.history.size(); ++row) {
    const std::vector<std::string>& r = stepped.history[row];
    const bool last_of_step = row + 1 == stepped.history.size() || stepped.history[row + 1][step] != r[step];
    if (!last_of_step) continue;
    ++steps_seen;
    EXPECT_EQ(std::stoi(r[step]), steps_seen);
    EXPECT_EQ(std::stod(r[time]), steps_seen == 1 ? 0.0 : 1.0);
    EXPECT_LT(std::stod(r[head]), 1e-4) << "pass " << r[0];
    EXPECT_LT(std::stod(r[moved]), 1e-4) << "pass " << r[0];
  }
  EXPECT_EQ(steps_seen, 2);

  const auto& a = stepped.summary["blocks"];
  const auto& b = direct.summary["blocks"];
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double u = b[i]["displacement"][0].get<double>();
    EXPECT_NEAR(a[i]["displacement"][0].get<double>(), u, 1e-3 * std::abs(u)) << "block " << i;
    for (int k = 0; k < 2; ++k) {
      const double s = b[i]["stress"][k].get<double>();
      EXPECT_NEAR(a[i]["stress"][k].get<double>(), s, 1e-6 * 1.0e7) << "block " << i;
    }
  }
}

}  // namespace
