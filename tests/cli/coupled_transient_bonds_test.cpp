// A coupled transient run's record of its broken bonds (docs/output.md, "Bonds"), on
// tests/cli/scenarios/bonded_crack_transient.toml: a crack of broken bonds under a pressure that
// rises over four 1 s steps, bonds breaking in each. Exact identities of the record, no
// tolerance:
// - history.csv's broken_bonds of each time step is the number of fractures.csv's bond rows of
//   that step (`step` the time step, `time` its end as history.csv has it), every bond listed
//   once;
// - bonds.pvd lists bonds_NNNN.vtu at t = 0 and the output times, figures/cracks.png is drawn;
// - a run stopped after its first step and resumed lists that step's breaks once, as the stopped
//   run wrote them, and writes the same files, byte for byte, as one never stopped
//   (checkpoint.bin's DDA state keeps the breaks, history.csv's counts give each its step).

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bond_record.hpp"
#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::bond_rows_of;
using hydrodda::testing::column_of;
using hydrodda::testing::expect_breaks_recorded;
using hydrodda::testing::expect_same_results;
using hydrodda::testing::read_csv;
using hydrodda::testing::read_file;
using hydrodda::testing::run_program;

namespace {

const fs::path kCrack = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/bonded_crack_transient.toml";

TEST(CoupledTransientBonds, EachTimeStepRecordsTheBondsItsIterationsBroke) {
  const auto out = hydrodda::testing::fresh_dir("hydrodda-transient-bonds-whole");
  const auto result = run_program("-q run " + kCrack.string() + " -o " + out.path.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto history = read_csv(out.path / "history.csv");
  ASSERT_EQ(history.size(), 6u) << "t = 0 and four steps";
  EXPECT_GE(expect_breaks_recorded(out.path, "step").rows_breaking, 2) << "bonds break in more than one step";
  const std::string series = read_file(out.path / "bonds.pvd");
  EXPECT_NE(series.find("timestep=\"0\" group=\"\" part=\"0\" file=\"bonds_0000.vtu\""), std::string::npos) << series;
  EXPECT_NE(series.find("timestep=\"2\" group=\"\" part=\"0\" file=\"bonds_0001.vtu\""), std::string::npos) << series;
  EXPECT_NE(series.find("timestep=\"4\" group=\"\" part=\"0\" file=\"bonds_0002.vtu\""), std::string::npos) << series;
  EXPECT_TRUE(fs::exists(out.path / "figures" / "cracks.png"));
}

TEST(CoupledTransientBonds, AResumedRunListsTheBreaksOfItsEarlierStepsOnce) {
  const auto parts = hydrodda::testing::fresh_dir("hydrodda-transient-bonds-resume");
  const auto stopped =
      run_program("-q run " + kCrack.string() + " -o " + parts.path.string() + " --threads 1 --stop-after 1");
  ASSERT_EQ(stopped.exit_code, 0) << stopped.output;
  const auto first_step = bond_rows_of(parts.path, "1");
  ASSERT_FALSE(first_step.empty());
  const auto resumed = run_program("-q run --resume " + parts.path.string() + " --threads 1");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(bond_rows_of(parts.path, "1"), first_step);
  EXPECT_GE(expect_breaks_recorded(parts.path, "step").rows_breaking, 2);
  const auto whole = hydrodda::testing::fresh_dir("hydrodda-transient-bonds-resume-whole");
  const auto first = run_program("-q run " + kCrack.string() + " -o " + whole.path.string() + " --threads 1");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  expect_same_results(whole.path, parts.path);
}

}  // namespace
