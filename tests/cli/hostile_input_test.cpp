// What a hostile user can throw at the program: every one ends with a message and exit code 1
// or 2, never a signal, an abort or an unbounded read.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

const fs::path kLoadedBlock = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/loaded_block.toml";

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-hostile-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

}  // namespace

TEST(HostileInput, ADeviceIsRefusedUnread) {
  const auto result = run_program("check /dev/zero");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("/dev/zero: is not a regular file"), std::string::npos) << result.output;
}

TEST(HostileInput, AFolderGivenAsTheScenarioIsNamedAsOne) {
  const fs::path dir = fresh_folder("folder.toml");
  fs::create_directories(dir);
  const auto result = run_program("check " + dir.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("is a folder, not a scenario file"), std::string::npos) << result.output;
  fs::remove_all(dir);
}

TEST(HostileInput, AnOversizedScenarioFileIsRefusedUnread) {
  const fs::path dir = fresh_folder("oversized");
  fs::create_directories(dir);
  const fs::path file = dir / "huge.toml";
  fs::copy_file(kLoadedBlock, file);
  fs::resize_file(file, (std::uintmax_t{16} << 20) + 1);  // a sparse tail of zeros
  const auto result = run_program("check " + file.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("is larger than 16 MiB"), std::string::npos) << result.output;
  fs::remove_all(dir);
}

TEST(HostileInput, AFolderInPlaceOfSummaryJsonIsAMessageNotAnAbort) {
  const fs::path out = fresh_folder("summary-folder");
  fs::create_directories(out / "summary.json");
  const auto result = run_program("run " + kLoadedBlock.string() + " -o " + out.string() + " --overwrite");
  EXPECT_TRUE(result.exit_code == 1 || result.exit_code == 2) << result.exit_code << "\n" << result.output;
  EXPECT_NE(result.output.find("summary.json: a folder of that name is in the way"), std::string::npos)
      << result.output;
  EXPECT_TRUE(fs::is_directory(out / "summary.json")) << "what the user had is left alone";
  fs::remove_all(out);
}

TEST(HostileInput, AnUnwritableRunFolderIsRefusedBeforeRunning) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes in any folder whatever its permissions";
  const fs::path out = fresh_folder("read-only");
  fs::create_directories(out);
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec);
  const auto result = run_program("run " + kLoadedBlock.string() + " -o " + out.string());
  fs::permissions(out, fs::perms::owner_all);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("cannot write in " + out.string()), std::string::npos) << result.output;
  fs::remove_all(out);
}
