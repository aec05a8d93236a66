// A breach search's record of its broken bonds (docs/breach.md, "The breach folder"), on
// tests/cli/scenarios/bonded_crack_coupled.toml: a crack of broken bonds whose tip bonds break as
// the pressure at its mouth is raised (0.5, 1, 1.5, 2 MPa; 30 passes a step, so that each step
// converges). Exact identities of the record, no tolerance:
// - breach.csv's broken_bonds of each step that held is the number of fractures.csv's bond rows
//   of that step (`step` the step, `time` its load), broken_bonds_total their running sum, every
//   bond listed once, as a run lists them by pass;
// - breach.json's last_held.broken_bonds names the bonds of the last held step's rows, in order;
// - bonds.pvd lists each held step's bonds_NNNN.vtu at its load, and figures/cracks.png is drawn.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "bond_record.hpp"
#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::column_of;
using hydrodda::testing::read_csv;
using hydrodda::testing::read_file;
using hydrodda::testing::run_program;

namespace {

const fs::path kCrack = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/bonded_crack_coupled.toml";

TEST(BreachBonds, EachStepThatHeldRecordsTheBondsItBrokeAndTheSummaryNamesTheLastStepsBonds) {
  const auto out = hydrodda::testing::fresh_dir("hydrodda-breach-bonds");
  const fs::path scenario =
      hydrodda::testing::edited_scenario(kCrack, "breach-bonds", {{"max_iterations = 3", "max_iterations = 30"}});
  const auto result = run_program("-q breach " + scenario.string() + " --vary 'flow.boundary[0].pressure' --from 5e5 " +
                                  "--to 2e6 --steps 3 -o " + out.path.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;

  const auto steps = read_csv(out.path / "breach.csv");
  const std::size_t step = column_of(steps[0], "step"), load = column_of(steps[0], "load");
  const std::size_t status = column_of(steps[0], "status"), broken = column_of(steps[0], "broken_bonds");
  const std::size_t total = column_of(steps[0], "broken_bonds_total");
  const auto fractures = read_csv(out.path / "fractures.csv");
  const std::size_t row_step = column_of(fractures[0], "step"), row_time = column_of(fractures[0], "time");
  const std::size_t origin = column_of(fractures[0], "origin"), number = column_of(fractures[0], "number");
  std::map<std::string, std::vector<int>> bonds_of_step;
  std::set<std::string> listed;
  for (std::size_t r = 1; r < fractures.size(); ++r) {
    if (fractures[r][origin] != "bond") continue;
    bonds_of_step[fractures[r][row_step]].push_back(std::stoi(fractures[r][number]));
    EXPECT_TRUE(listed.insert(fractures[r][number]).second) << "bond " << fractures[r][number] << " listed twice";
    for (std::size_t s = 1; s < steps.size(); ++s) {
      if (steps[s][step] == fractures[r][row_step]) {
        EXPECT_EQ(fractures[r][row_time], steps[s][load]);
      }
    }
  }
  int running = 0;
  std::string last_held;
  for (std::size_t s = 1; s < steps.size(); ++s) {
    ASSERT_EQ(steps[s][status], "held") << "step " << steps[s][step];
    const int in_step = std::stoi(steps[s][broken]);
    EXPECT_EQ(in_step, static_cast<int>(bonds_of_step[steps[s][step]].size())) << "step " << steps[s][step];
    running += in_step;
    EXPECT_EQ(std::stoi(steps[s][total]), running) << "step " << steps[s][step];
    const std::string file = "bonds_" + std::string(4 - steps[s][step].size(), '0') + steps[s][step] + ".vtu";
    EXPECT_NE(read_file(out.path / "bonds.pvd").find("timestep=\"" + steps[s][load] + "\" group=\"\" part=\"0\" file=\"" + file),
              std::string::npos) << file;
    last_held = steps[s][step];
  }
  EXPECT_GT(running, 0) << "the crack grows between 0.5 and 2 MPa";
  EXPECT_EQ(running, static_cast<int>(listed.size()));

  std::ifstream in(out.path / "breach.json");
  const nlohmann::json breach = nlohmann::json::parse(in);
  EXPECT_EQ(breach["last_held"]["broken_bonds"].get<std::vector<int>>(), bonds_of_step[last_held]);
  EXPECT_FALSE(bonds_of_step[last_held].empty()) << "the last step breaks bonds";
  EXPECT_EQ(breach["last_held"]["broken_bonds_total"].get<int>(), running);
  EXPECT_TRUE(fs::exists(out.path / "figures" / "cracks.png"));
}

}  // namespace
