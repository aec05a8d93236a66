// A coupled run's record of its broken bonds (docs/output.md, "Bonds"), on
// tests/cli/scenarios/bonded_crack_coupled.toml: a crack of broken bonds under fluid pressure
// whose tip bonds break pass by pass. Exact identities of the record, no tolerance:
// - history.csv's broken_bonds of each pass is the number of fractures.csv's bond rows of that
//   pass (`step` the pass, `time` the pass's as history.csv has it), every bond listed once;
// - bonds.pvd lists the written passes and figures/cracks.png is drawn;
// - a run stopped after its first pass and resumed lists the first pass's breaks once, as the
//   stopped run wrote them (history.csv's counts give each earlier break its pass), and writes
//   the same files, byte for byte, as one never stopped (checkpoint.bin keeps the breaks).

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "run_folder_compare.hpp"
#include "bond_record.hpp"
#include "result_files.hpp"
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

const fs::path kCrack = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/bonded_crack_coupled.toml";

TEST(CoupledBonds, EachPassRecordsTheBondsItsStepsBroke) {
  const auto out = hydrodda::testing::fresh_dir("hydrodda-coupled-bonds-whole");
  const auto result = run_program("-q run " + kCrack.string() + " -o " + out.path.string() + " --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto history = read_csv(out.path / "history.csv");
  ASSERT_EQ(history.size(), 4u) << "three passes";
  EXPECT_GT(std::stoi(history[1][column_of(history[0], "broken_bonds")]), 0) << "the first pass breaks bonds";
  EXPECT_GT(expect_breaks_recorded(out.path, "iteration").total, 0);
  const std::string series = read_file(out.path / "bonds.pvd");
  EXPECT_NE(series.find("bonds_0001.vtu"), std::string::npos) << series;
  EXPECT_NE(series.find("bonds_0003.vtu"), std::string::npos) << series;
  EXPECT_TRUE(fs::exists(out.path / "figures" / "cracks.png"));
}

// Stopped after its first pass and resumed, the run lists the first pass's breaks once, as the
// stopped run wrote them, and each later pass's with it; bonds.pvd keeps the first pass's file.
TEST(CoupledBonds, AResumedRunListsTheBreaksOfItsEarlierPassesOnce) {
  const auto parts = hydrodda::testing::fresh_dir("hydrodda-coupled-bonds-resume");
  const auto stopped = run_program("-q run " + kCrack.string() + " -o " + parts.path.string() +
                                   " --threads 1 --stop-after 1");
  ASSERT_EQ(stopped.exit_code, 0) << stopped.output;
  const auto first_pass = bond_rows_of(parts.path, "1");
  ASSERT_FALSE(first_pass.empty());
  const auto resumed = run_program("-q run --resume " + parts.path.string() + " --threads 1");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(bond_rows_of(parts.path, "1"), first_pass);
  EXPECT_GE(expect_breaks_recorded(parts.path, "iteration").total, static_cast<int>(first_pass.size()));
  const std::string series = read_file(parts.path / "bonds.pvd");
  EXPECT_NE(series.find("bonds_0001.vtu"), std::string::npos) << series;
  EXPECT_NE(series.find("bonds_0003.vtu"), std::string::npos) << series;
  // And the run is the one never stopped, byte for byte: the checkpoint keeps the bonds broken
  // so far (before it did not, and the resumed run broke the first pass's bonds again).
  const auto whole = hydrodda::testing::fresh_dir("hydrodda-coupled-bonds-resume-whole");
  const auto first = run_program("-q run " + kCrack.string() + " -o " + whole.path.string() + " --threads 1");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  expect_same_results(whole.path, parts.path);
}

}  // namespace
