// The command line as a user meets it: versions, help, exit codes, the run folder's safety.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

fs::path scenario_file(const std::string& relative) { return fs::path(HYDRODDA_SOURCE_DIR) / relative; }

TEST(Program, VersionAndHelp) {
  const auto version = run_program("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find("hydrodda "), std::string::npos);
  const auto help = run_program("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("run"), std::string::npos);
  EXPECT_NE(help.output.find("check"), std::string::npos);
}

TEST(Program, NoSubcommandIsBadInput) {
  const auto result = run_program("");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("subcommand"), std::string::npos) << result.output;
}

TEST(Program, MissingScenarioFileIsBadInput) {
  const auto result = run_program("check no-such-file.toml");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("no-such-file.toml: cannot open the scenario file"), std::string::npos)
      << result.output;
}

TEST(Program, ErrorsAreAllReportedTogether) {
  const fs::path file = fs::temp_directory_path() / "hydrodda-many-errors.toml";
  std::ofstream(file) << "[geometry]\n"
                         "[[geometry.block]]\n"
                         "vertices = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]\n"
                         "[material.rock]\n"
                         "density = -1.0\n"
                         "young = 1.0e10\n"
                         "poison = 0.3\n"
                         "[mechanics]\n"
                         "time_step = -1.0\n"
                         "analysis = \"dynamic\"\n";
  const auto result = run_program("check " + file.string());
  EXPECT_EQ(result.exit_code, 2);
  const std::string name = file.string();
  EXPECT_NE(result.output.find(name + ":3: geometry.block.vertices: vertices run clockwise"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find(name + ":5: material.rock.density: must be > 0"), std::string::npos);
  EXPECT_NE(result.output.find(name + ":7: material.rock.poison: unknown key (did you mean 'poisson'?)"),
            std::string::npos);
  EXPECT_NE(result.output.find(name + ":9: mechanics.time_step: must be > 0"), std::string::npos);
  EXPECT_NE(result.output.find("material.rock.poisson: required by [mechanics]"), std::string::npos);
  EXPECT_NE(result.output.find("5 error(s)"), std::string::npos) << result.output;
}

TEST(Program, CheckAcceptsTheContractExample) {
  const auto result = run_program("check " + scenario_file("scenarios/examples/contract.toml").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find(": OK (coupled run"), std::string::npos) << result.output;
}

TEST(Program, RunRefusesAFolderThatHoldsFiles) {
  const fs::path out = fs::temp_directory_path() / "hydrodda-occupied";
  fs::remove_all(out);
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "a user's file\n";
  const auto result =
      run_program("run " + scenario_file("scenarios/examples/contract.toml").string() + " -o " + out.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("already holds files"), std::string::npos) << result.output;
  std::ifstream notes(out / "notes.txt");
  std::string kept;
  std::getline(notes, kept);
  EXPECT_EQ(kept, "a user's file");
  fs::remove_all(out);
}

}  // namespace
