// `hydrodda breach` through the real program: what it refuses before building anything, a
// limit on a summary.json value, and a folder it will not overwrite.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

const fs::path kSource = HYDRODDA_SOURCE_DIR;
const fs::path kJacking = kSource / "scenarios/verification/breach_hydraulic_jacking.toml";
const std::string kMouths = " --vary 'flow.boundary[0].head' --vary 'flow.boundary[1].head'";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string full_precision(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST(BreachCommand, RefusesWhatItCannotSearchBeforeBuildingAnything) {
  const fs::path out = fresh_dir("hydrodda-breach-refused");
  const std::string base = "breach " + kJacking.string() + " -o " + out.string();
  struct Case {
    std::string arguments, expected;
  };
  const std::vector<Case> cases{
      {" --vary coupling.relaxation --from 0.5 --to 1", "--vary coupling.relaxation: a loading path varies"},
      {" --vary 'flow.boundary[7].head' --from 2 --to 3", "flow.boundary[7]"},
      {kMouths + " --from 2 --to 2", "--from and --to are both 2"},
      {kMouths + " --from 2 --to 3 --tolerance 1.5", "--tolerance must be between 0 and 1"},
      {kMouths + " --from 2 --to 3 --limit flow.boundaries.top", "--limit 'flow.boundaries.top': give PATH=VALUE"},
      {kMouths + " --from 2 --to 3 --limit flow.boundaries.top=lots", "'lots' is not a number"},
  };
  for (const Case& c : cases) {
    const auto result = run_program(base + c.arguments);
    EXPECT_EQ(result.exit_code, 2) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.expected), std::string::npos) << c.arguments << "\n" << result.output;
    EXPECT_FALSE(fs::exists(out / "breach.csv")) << c.arguments;
  }
  const auto flow_only = run_program("breach " + (kSource / "scenarios/verification/flow_linear_head.toml").string() +
                                     " --vary 'flow.boundary[0].head' --from 1 --to 2 -o " + out.string());
  EXPECT_EQ(flow_only.exit_code, 2) << flow_only.output;
  EXPECT_NE(flow_only.output.find("takes a coupled scenario"), std::string::npos) << flow_only.output;
  fs::remove_all(out);
}

// Darcy's law is linear: with the joint closed at its residual aperture (the block at rest below
// H* = 2.5 m) the flow out of the top is c H exactly. A limit on that flow at c × 2.3 m is the
// breach the search must bracket, within its tolerance, as "beyond limit".
TEST(BreachCommand, ALimitOnASummaryValueIsTheBreachWhenItIsPassed) {
  const fs::path out = fresh_dir("hydrodda-breach-limit");
  const auto first = run_program("breach " + kJacking.string() + kMouths + " --from 2.0 --to 2.2 --steps 1 -o " +
                                 out.string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const double c = read_json(out / "steps/step_000.json")["flow"]["boundaries"]["top"].get<double>() / 2.0;
  ASSERT_GT(c, 0.0);
  const auto limited = run_program("breach " + kJacking.string() + kMouths + " --from 2.0 --to 2.45 --steps 3" +
                                   " --tolerance 0.002 --overwrite --limit flow.boundaries.top=" +
                                   full_precision(c * 2.3) + " -o " + out.string());
  ASSERT_EQ(limited.exit_code, 0) << limited.output;
  const nlohmann::json breach = read_json(out / "breach.json");
  EXPECT_EQ(breach["broken_status"], "beyond limit");
  EXPECT_LE(breach["held"].get<double>(), 2.3 * (1 + 1e-6));
  EXPECT_GE(breach["broken"].get<double>(), 2.3 * (1 - 1e-6));
  EXPECT_LE(breach["broken"].get<double>() - breach["held"].get<double>(), 0.002 * 2.3 * 1.01);
  fs::remove_all(out);
}

TEST(BreachCommand, LeavesAFolderThatHoldsFilesAsItWas) {
  const fs::path out = fresh_dir("hydrodda-breach-kept");
  fs::create_directories(out);
  std::ofstream(out / "breach.csv") << "mine\n";
  const auto result = run_program("breach " + kJacking.string() + kMouths + " --from 2 --to 3 -o " + out.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  std::ifstream in(out / "breach.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "mine");
  fs::remove_all(out);
}
