// --overwrite replaces a run's own files and nothing of the user's: the current folder (a
// user's scenario.toml there) is refused, and so is a figures/ that links out of the run folder.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::fresh_dir;
using hydrodda::testing::read_file;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

const fs::path kSource = HYDRODDA_SOURCE_DIR;

}  // namespace

// `-o . --overwrite` from a folder holding the user's own scenario.toml: a coupled run would
// write its copy of the scenario over it. Refused (exit 2), the file kept.
TEST(Overwrite, TheCurrentFolderIsRefusedAndTheUsersScenarioKept) {
  const auto folder = fresh_dir("hydrodda-overwrite-here");
  fs::create_directories(folder.path);
  const std::string mine = "title = \"my own model, not the run's\"\n";
  std::ofstream(folder.path / "scenario.toml") << mine;
  const auto result = run_command("cd " + folder.path.string() + " && " + HYDRODDA_BINARY + " run " +
                                  (kSource / "scenarios/paper/six_block_lr_rl.toml").string() + " -o . --overwrite");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("--overwrite is refused"), std::string::npos) << result.output;
  EXPECT_EQ(read_file(folder.path / "scenario.toml"), mine);
  EXPECT_FALSE(fs::exists(folder.path / "summary.json"));
}

// A figures/ in the run folder that links elsewhere: the run's figures would be written there,
// over the user's files of the same names. Refused before the run, nothing outside touched.
TEST(Overwrite, AFiguresLinkOutOfTheRunFolderIsRefused) {
  const auto folder = fresh_dir("hydrodda-overwrite-link");
  const fs::path outside = folder.path / "outside", run = folder.path / "run";
  fs::create_directories(outside);
  fs::create_directories(run);
  std::ofstream(outside / "heads.png") << "the user's own picture";
  fs::create_directory_symlink(outside, run / "figures");
  const auto result = run_program("run " + (kSource / "scenarios/verification/flow_linear_head.toml").string() +
                                  " -o " + run.string() + " --overwrite");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("symbolic link"), std::string::npos) << result.output;
  EXPECT_EQ(read_file(outside / "heads.png"), "the user's own picture");
  EXPECT_EQ(std::distance(fs::directory_iterator(outside), fs::directory_iterator{}), 1);
}
