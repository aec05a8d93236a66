// What a coupled run records every pass, through the real program: measure.csv (one row per
// pass and measured point) and each flow region's flow and effective conductivity in
// history.csv. The last pass's rows are the state summary.json describes, so they must agree
// with it to the 17 digits both print; a run stopped after pass 1 and resumed writes the same
// files as one never stopped.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::column;
using hydrodda::testing::expect_same_results;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

// A coupled run with one measured point (A) and one flow region (core), 4 passes, a few seconds.
const fs::path kContract = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/contract.toml";

struct Folder : hydrodda::testing::TemporaryFolder {
  explicit Folder(const std::string& name) : TemporaryFolder("hydrodda-monitoring-" + name) {}
};

TEST(CoupledMonitoring, MeasureAndRegionFlowsEveryPass) {
  Folder out("every-pass");
  const auto result = run_program("run " + kContract.string() + " -o " + out.path.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto summary = nlohmann::json::parse(std::ifstream(out.path / "summary.json"));
  const int passes = summary["iterations"];
  ASSERT_GE(passes, 2);

  const auto measure = read_csv(out.path / "measure.csv");
  ASSERT_EQ(measure.size(), static_cast<std::size_t>(passes) + 1);  // one point, header
  EXPECT_EQ(measure[0], (std::vector<std::string>{"iteration", "time", "name", "x", "y", "ux", "uy"}));
  for (int k = 1; k <= passes; ++k) {
    EXPECT_EQ(measure[k][0], std::to_string(k));
    EXPECT_EQ(measure[k][2], "A");
  }
  const auto& a = summary["measure"]["A"];
  const auto& last = measure.back();
  EXPECT_EQ(std::stod(last[3]), a["position"][0].get<double>());
  EXPECT_EQ(std::stod(last[4]), a["position"][1].get<double>());
  EXPECT_EQ(std::stod(last[5]), a["displacement"][0].get<double>());
  EXPECT_EQ(std::stod(last[6]), a["displacement"][1].get<double>());
  // The point moves (the wedge settles), so a column of zeros would fail here.
  EXPECT_GT(std::abs(std::stod(last[6])), 1e-4);

  const auto history = read_csv(out.path / "history.csv");
  ASSERT_EQ(history.size(), static_cast<std::size_t>(passes) + 1);
  const int flow = column(history[0], "region_flow_core");
  const int conductivity = column(history[0], "region_conductivity_core");
  const auto& core = summary["flow"]["regions"]["core"];
  EXPECT_EQ(std::stod(history.back()[flow]), core["flow"].get<double>());
  EXPECT_EQ(std::stod(history.back()[conductivity]), core["effective_conductivity"].get<double>());
  EXPECT_GT(std::stod(history.back()[conductivity]), 0.0);
}

TEST(CoupledMonitoring, ResumedRunWritesTheSameMeasureRows) {
  Folder whole("whole"), parts("parts");
  ASSERT_EQ(run_program("run " + kContract.string() + " -o " + whole.path.string()).exit_code, 0);
  const auto first = run_program("run " + kContract.string() + " -o " + parts.path.string() + " --stop-after 1");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_EQ(read_csv(parts.path / "measure.csv").size(), 2u);
  const auto second = run_program("run --resume " + parts.path.string());
  ASSERT_EQ(second.exit_code, 0) << second.output;
  expect_same_results(whole.path, parts.path);  // measure.csv and history.csv included
}

}  // namespace
