// `hydrodda breach` on a model that holds mechanically while its loop swings, through the real
// program: the faulted seal (scenarios/examples/faulted_seal.toml) with each point of its joints
// open by its own gap (`[joint] hydraulic_opening = "local"`: by default it converges at both
// loads) converges at 1,000 m of overpressure head and swings at 1,500 m (0.58 of its hand
// jacking head), its blocks at rest
// after every pass and a hundred joint crossings opening and shutting
// (docs/studies/2026-11-29-loop-convergence.md). By default that step holds, "held, unsettled",
// its K_eff/K_m given as a range; with --converged-only it is the breach.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
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

const std::string kLoads = " --vary 'flow.boundary[0].head' --from 1045 --to 1545 --steps 1 --threads 1";

// The seal with 20 passes a step (1,000 m converges in 12, its load ramped, and 20 are enough to range the swing
// at 1,500 m over its last 10), drawing its figures.
fs::path seal_of_20_passes(const std::string& name) {
  return edited_scenario(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/faulted_seal.toml",
                         name + "-" + std::to_string(::getpid()),
                         {{"max_iterations = 50", "max_iterations = 20"},
                          {"figures = []", "figures = [\"png\"]"},
                          {"friction_angle = 30.0", "friction_angle = 30.0\nhydraulic_opening = \"local\""}});
}

nlohmann::json read_json(const fs::path& file) { return nlohmann::json::parse(std::ifstream(file)); }

}  // namespace

TEST(BreachUnsettled, ASealThatSwingsAtRestHoldsAndItsAnswerIsARange) {
  const fs::path seal = seal_of_20_passes("hydrodda-breach-unsettled");
  const auto out = hydrodda::testing::fresh_dir("hydrodda-breach-unsettled-out");
  const auto result = run_program("breach " + seal.string() + kLoads + " -o " + out.path.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto rows = read_csv(out.path / "breach.csv");
  ASSERT_EQ(rows.size(), 3u);  // header, 1,000 m, 1,500 m
  const auto& header = rows[0];
  const auto at = [&](std::size_t row, const std::string& name) { return rows[row][column(header, name)]; };
  const std::string k = "flow.regions.seal.normalised_conductivity";
  EXPECT_EQ(at(1, "status"), "held");
  EXPECT_FALSE(at(1, k).empty());
  EXPECT_TRUE(at(1, k + "_least").empty());
  EXPECT_EQ(at(2, "status"), "held, unsettled");
  EXPECT_EQ(at(2, "passes"), "20");
  // An unsettled answer is a range, not one number.
  EXPECT_TRUE(at(2, k).empty());
  const double least = std::stod(at(2, k + "_least")), largest = std::stod(at(2, k + "_largest"));
  EXPECT_LT(least, largest);  // it swings: measured 6.03 to 6.26
  EXPECT_GT(least, 1.0);
  // Why it is unsettled: the last pass's norms, and (its blocks' change above the tolerance)
  // the blocks that moved most in that pass.
  const std::string why = at(2, "message");
  EXPECT_NE(why.find("; at its last pass the head change "), std::string::npos) << why;
  EXPECT_NE(why.find("(tolerance 0.0001); in the last pass block "), std::string::npos) << why;

  // The step's state, as summary.json: not converged, with the same range over its last 10.
  const nlohmann::json step = read_json(out.path / "steps/step_001.json");
  EXPECT_EQ(step["converged"], false);
  const nlohmann::json& range = step["flow"]["regions"]["seal"]["last_passes"];
  EXPECT_EQ(range["passes"], 10);
  EXPECT_DOUBLE_EQ(range["least"].get<double>(), least);
  EXPECT_DOUBLE_EQ(range["largest"].get<double>(), largest);

  const nlohmann::json breach = read_json(out.path / "breach.json");
  EXPECT_EQ(breach["rule"], "mechanical");
  EXPECT_TRUE(breach["broken"].is_null());
  EXPECT_DOUBLE_EQ(breach["held"].get<double>(), 1545.0);
  EXPECT_EQ(breach["unsettled_held"], 1);
  EXPECT_DOUBLE_EQ(breach["worst_unsettled_spread"]["spread"].get<double>(), (largest - least) / largest);
  EXPECT_EQ(breach["worst_unsettled_spread"]["region"], "seal");
  EXPECT_EQ(breach["last_held"]["unsettled"], true);
  EXPECT_DOUBLE_EQ(breach["last_held"]["normalised_conductivity_range"]["seal"]["least"].get<double>(), least);
  const std::string verdict = breach["verdict"];
  EXPECT_NE(verdict.find("1 step below it held unsettled"), std::string::npos) << verdict;
  EXPECT_TRUE(fs::exists(out.path / "figures/breach.png"));
}

TEST(BreachUnsettled, ConvergedOnlyMakesTheUnsettledStepTheBreach) {
  const fs::path seal = seal_of_20_passes("hydrodda-breach-converged-only");
  const auto out = hydrodda::testing::fresh_dir("hydrodda-breach-converged-only-out");
  // A bracket 32% wide is within --tolerance 0.4: no bisection.
  const auto result =
      run_program("breach " + seal.string() + kLoads + " --tolerance 0.4 --converged-only -o " + out.path.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const nlohmann::json breach = read_json(out.path / "breach.json");
  EXPECT_EQ(breach["rule"], "converged only");
  EXPECT_DOUBLE_EQ(breach["held"].get<double>(), 1045.0);
  EXPECT_DOUBLE_EQ(breach["broken"].get<double>(), 1545.0);
  EXPECT_EQ(breach["broken_status"], "held, unsettled");
  EXPECT_EQ(breach["unsettled_held"], 0);
  EXPECT_EQ(breach["last_held"]["unsettled"], false);
  const std::string verdict = breach["verdict"];
  EXPECT_EQ(verdict.rfind("converged-only breach between", 0), 0u) << verdict;
}

// A --limit on the seal's K_eff/K_m at 6.1, inside the unsettled step's swing (measured 6.03 to
// 6.26 over its last 10 passes) and above the converged step's: the unsettled state passed the
// bound in some of its last passes, so it is beyond the limit (it held, unsettled, before the
// limit looked at it), the breach is there, and breach.csv still gives its answer as a range.
TEST(BreachUnsettled, AnUnsettledStepWhoseSwingPassesTheLimitIsBeyondIt) {
  const fs::path seal = seal_of_20_passes("hydrodda-breach-unsettled-limit");
  const auto out = hydrodda::testing::fresh_dir("hydrodda-breach-unsettled-limit-out");
  const std::string k = "flow.regions.seal.normalised_conductivity";
  const auto result = run_program("breach " + seal.string() + kLoads + " --tolerance 0.4 --limit " + k + "=6.1 -o " +
                                  out.path.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto rows = read_csv(out.path / "breach.csv");
  ASSERT_EQ(rows.size(), 3u);
  const auto& header = rows[0];
  const auto at = [&](std::size_t row, const std::string& name) { return rows[row][column(header, name)]; };
  EXPECT_EQ(at(1, "status"), "held");
  EXPECT_LT(std::stod(at(1, k)), 6.1);
  EXPECT_EQ(at(2, "status"), "beyond limit");
  EXPECT_TRUE(at(2, k).empty());
  const double least = std::stod(at(2, k + "_least")), largest = std::stod(at(2, k + "_largest"));
  EXPECT_LT(least, largest);
  EXPECT_GT(largest, 6.1);
  EXPECT_NE(at(2, "message").find("over its last passes is above the limit"), std::string::npos) << at(2, "message");
  EXPECT_EQ(read_json(out.path / "steps/step_001.json")["converged"], false);
  const nlohmann::json breach = read_json(out.path / "breach.json");
  EXPECT_DOUBLE_EQ(breach["held"].get<double>(), 1045.0);
  EXPECT_DOUBLE_EQ(breach["broken"].get<double>(), 1545.0);
  EXPECT_EQ(breach["broken_status"], "beyond limit");
}
