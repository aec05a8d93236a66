// Boundary gaps are not fractures (docs/coupling.md, "Boundary gaps are not fractures"), through
// the program on the paper's scenarios: the strip a moved boundary leaves carries no flow along
// it, and strips along the base and top of the flexing layer do not change its conductivity.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <unistd.h>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

// Runs a paper scenario with extra flow regions appended (each refines the mesh along its sides,
// so the strips are resolved) and returns summary.json.
nlohmann::json run_with_regions(const std::string& paper, const std::string& regions, const std::string& tag) {
  std::ifstream in(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper" / paper);
  std::stringstream text;
  text << in.rdbuf();
  std::string scenario = text.str();
  // No figures: the flow is what is measured.
  if (const auto at = scenario.find("figures = [\"png\"]"); at != std::string::npos)
    scenario.replace(at, 17, "figures = []");
  scenario += "\n" + regions;
  const fs::path folder = fs::temp_directory_path() / ("hydrodda-gap-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  std::ofstream(folder / "scenario.toml") << scenario;
  const auto result = run_program("-q run " + (folder / "scenario.toml").string() + " -o " + (folder / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  std::ifstream summary(folder / "out/summary.json");
  nlohmann::json out = summary ? nlohmann::json::parse(summary) : nlohmann::json::object();
  fs::remove_all(folder);
  return out;
}

}  // namespace

// Six blocks shortened left–right by 5 mm, flow bottom to top: the right side moves in, leaving
// a 5 mm strip along the no-flow right boundary. A region over that strip carries under 0.1% of
// the model's flow: what 5 mm of intact rock carries, (0.005 / 5) K_m / K_eff = 0.098%. Before
// the strip was taken out of the open area it carried 99% of the flow, as a channel.
TEST(BoundaryGap, StripAlongTheMovedNoFlowSideCarriesNoFlow) {
  const nlohmann::json s = run_with_regions(
      "six_block_lr_bt.toml", "[[flow.region]]\nname = \"strip\"\npolygon = [[4.995, 0.0], [5.0, 0.0], [5.0, 5.0], [4.995, 5.0]]\n",
      "lr-bt");
  ASSERT_TRUE(s.contains("flow"));
  EXPECT_EQ(s["converged"], true);
  const double strip = s["flow"]["regions"]["strip"]["flow"], model = s["flow"]["regions"]["model"]["flow"];
  EXPECT_GT(model, 0.0);
  EXPECT_LT(std::abs(strip), 1e-3 * model) << "strip " << strip << " of " << model;
  // The blocks settle under gravity and the shortening by elastic amounts only: their vertices
  // reach outside the mesh by less than 0.1 mm (measured 3.8e-5 m), and the run says so.
  ASSERT_TRUE(s.contains("outside_mesh"));
  EXPECT_LT(s["outside_mesh"]["largest_distance"].get<double>(), 1e-4);
}

// The symmetric flexure at 20 m: the layer lifts off the base (head 20 m), and the gap it leaves
// belongs to the base's reservoir. The central region's normalised conductivity is the same,
// within 1%, whether or not 5 cm strips at its base and top are part of it (before: 1.0271
// against 1.0096, the gap carrying 64% of the rise).
TEST(BoundaryGap, FlexureConductivityDoesNotDependOnTheStripsAlongBaseAndTop) {
  const nlohmann::json s = run_with_regions(
      "symmetric_flexure_20m.toml",
      "[[flow.region]]\nname = \"inner\"\npolygon = [[4.0, 0.05], [12.0, 0.05], [12.0, 1.95], [4.0, 1.95]]\n", "flexure");
  ASSERT_TRUE(s.contains("flow"));
  EXPECT_EQ(s["converged"], true);
  const double whole = s["flow"]["regions"]["fractured"]["normalised_conductivity"];
  const double inner = s["flow"]["regions"]["inner"]["normalised_conductivity"];
  EXPECT_GT(whole, 1.0);
  EXPECT_NEAR(whole, inner, 0.01 * inner);
}
