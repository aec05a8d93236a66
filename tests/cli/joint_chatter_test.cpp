// A coupled run whose joints open and shut from pass to pass, through the real program: the
// faulted seal at 1,500 m of head (0.58 of its hand jacking head) with each point of its joints
// open by its own gap (`[joint] hydraulic_opening = "local"`; by default a face that carries a
// force is closed along its length, and the loop converges), whose loop swings with a hundred and
// more joint crossings switching every pass (docs/studies/2026-11-29-loop-convergence.md).
// Its message (after the drift it reads as, the seal rising a little each pass) says that the
// joints chatter, with the median crossings and contacts of
// history.csv's passes, and advises no relaxation or acceleration of the heads.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "result_files.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::column;
using hydrodda::testing::edited_scenario;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

// The median of a column over the passes the diagnosis fits: the last ten, the first left out.
long long median_of_last_passes(const std::vector<std::vector<std::string>>& history, const std::string& name) {
  const int c = column(history[0], name);
  std::vector<long long> values;
  const std::size_t rows = history.size() - 1;  // passes, after the header
  for (std::size_t pass = std::max<std::size_t>(2, rows > 10 ? rows - 9 : 2); pass <= rows; ++pass)
    values.push_back(std::stoll(history[pass][static_cast<std::size_t>(c)]));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

TEST(JointChatter, AFaultedSealWhoseJointsOpenAndShutSaysSo) {
  const fs::path seal = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/faulted_seal.toml";
  const fs::path file = edited_scenario(seal, "hydrodda-joint-chatter",
                                        {{"head = 1045.0", "head = 1545.0"},
                                         {"max_iterations = 50", "max_iterations = 14"},
                                         {"friction_angle = 30.0", "friction_angle = 30.0\nhydraulic_opening = \"local\""}});
  hydrodda::testing::TemporaryFolder out("hydrodda-joint-chatter-out");
  const auto result = run_program("-q run " + file.string() + " -o " + out.path.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto summary = nlohmann::json::parse(std::ifstream(out.path / "summary.json"));
  EXPECT_EQ(summary["converged"], false);
  const std::string message = summary["message"];
  const auto history = read_csv(out.path / "history.csv");
  ASSERT_EQ(history.size(), 15u);
  const long long crossings = median_of_last_passes(history, "joint_crossings_switched");
  const long long contacts = median_of_last_passes(history, "contact_state_changes");
  EXPECT_GE(crossings, 10);  // measured: 143
  EXPECT_NE(message.find("the joints open and shut from pass to pass (a median of " + std::to_string(crossings) +
                         " of their crossings with fluid elements switched between open and closed, and " +
                         std::to_string(contacts) + " contacts changed state, a pass)"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find("anderson"), std::string::npos) << message;
  EXPECT_NE(message.find("try \"face\""), std::string::npos) << message;
  EXPECT_EQ(message.find("coupling.relaxation = "), std::string::npos) << message;
  EXPECT_NE(message.find("K_eff/K_m of region 'seal' ranged from"), std::string::npos) << message;
}

}  // namespace
