// What a hostile user can throw at the program: every one ends with a message and exit code 1
// or 2, never a signal, an abort or an unbounded read.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_command;
using hydrodda::testing::run_program;

namespace {

const fs::path kLoadedBlock = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/loaded_block.toml";

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-hostile-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

// A flow scenario in `dir` whose `key` (geometry.fractures_file or mesh.file) names `named`.
fs::path scenario_naming(const fs::path& dir, const std::string& key, const fs::path& named) {
  const fs::path file = dir / "named.toml";
  std::ofstream out(file);
  out << "[geometry]\ndomain = [[0.0, 0.0], [5.0, 0.0], [5.0, 5.0], [0.0, 5.0]]\n";
  if (key == "geometry.fractures_file") out << "fractures_file = \"" << named.string() << "\"\n";
  out << "[material.rock]\nmatrix_porosity = 0.1\ngrain_diameter = 1.0e-5\n"
         "[flow]\n[[flow.boundary]]\nname = \"left\"\nhead = 1.0\n";
  if (key == "mesh.file") out << "[mesh]\nfile = \"" << named.string() << "\"\n";
  return file;
}

// `check` under a timeout, a guard only: a pipe opened would block it until killed, and what
// the tests assert is its message and exit code.
hydrodda::testing::ProgramResult check_guarded(const fs::path& scenario) {
  return run_command("timeout 120 " + std::string(HYDRODDA_BINARY) + " check " + scenario.string());
}

const std::vector<std::string> kNamedFileKeys = {"geometry.fractures_file", "mesh.file"};

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

// Root writes in any folder whatever its permissions, so as root the folder is made immutable
// instead (chattr +i: not even root may add a file to it), and made writable again afterwards.
TEST(HostileInput, AnUnwritableRunFolderIsRefusedBeforeRunning) {
  const fs::path out = fresh_folder("read-only");
  fs::create_directories(out);
  const bool root = ::geteuid() == 0;
  if (root && run_command("chattr +i " + out.string()).exit_code != 0) {
    fs::remove_all(out);
    GTEST_SKIP() << "root writes in any folder whatever its permissions, and chattr +i is refused here";
  }
  if (!root) fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec);
  const auto result = run_program("run " + kLoadedBlock.string() + " -o " + out.string());
  if (root) run_command("chattr -i " + out.string());
  fs::permissions(out, fs::perms::owner_all);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("cannot write in " + out.string()), std::string::npos) << result.output;
  fs::remove_all(out);
}

TEST(HostileInput, APolygonTooDetailedToMeshInBoundedTimeIsRefusedByCheck) {
  const fs::path dir = fresh_folder("detailed-region");
  fs::create_directories(dir);
  const fs::path file = dir / "detailed_region.toml";
  std::ofstream out(file);
  out << "[geometry]\ndomain = [[0.0, 0.0], [5.0, 0.0], [5.0, 5.0], [0.0, 5.0]]\n"
         "[material.rock]\nmatrix_porosity = 0.1\ngrain_diameter = 1.0e-5\n"
         "[flow]\n[[flow.boundary]]\nname = \"left\"\nhead = 1.0\n"
         "[[flow.region]]\nname = \"core\"\npermeability = 1e-12\npolygon = [";
  const int n = 100'000;  // a circle of radius 2 about (2.5, 2.5)
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * 3.14159265358979 * i / n;
    out << (i ? ", " : "") << "[" << 2.5 + 2.0 * std::cos(angle) << ", " << 2.5 + 2.0 * std::sin(angle) << "]";
  }
  out << "]\n";
  out.close();
  const auto result = run_program("check " + file.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find(":13: flow.region.polygon: a polygon of 100000 vertices; at most 2000"),
            std::string::npos)
      << result.output;
  fs::remove_all(dir);
}

// Item 18's command-line messages: each says what is wanted, in the user's terms.
TEST(HostileInput, CommandLineMistakesSayWhatIsWanted) {
  const std::string sweep = "sweep " + kLoadedBlock.string() + " --set mechanics.steps=10,20";
  for (const std::string& arguments : {sweep + " --jobs 0", "run " + kLoadedBlock.string() + " --stop-after 0"}) {
    const auto result = run_program(arguments);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("must be a whole number >= 1, got 0"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("1.79"), std::string::npos) << result.output;
  }
  // -o '' was ignored: the run went to output.directory.
  for (const std::string& arguments : {"run " + kLoadedBlock.string() + " -o ''", sweep + " -o ''"}) {
    const auto result = run_program(arguments);
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--output: the folder's path is empty"), std::string::npos) << result.output;
  }
  // -o at a symbolic link to nothing said "File exists".
  const fs::path dir = fresh_folder("dangling");
  fs::create_directories(dir);
  fs::create_symlink(dir / "gone", dir / "link");
  const auto dangling = run_program("run " + kLoadedBlock.string() + " -o " + (dir / "link").string());
  EXPECT_EQ(dangling.exit_code, 2) << dangling.output;
  EXPECT_NE(dangling.output.find("is a symbolic link to " + (dir / "gone").string() + ", which does not exist"),
            std::string::npos)
      << dangling.output;
  EXPECT_FALSE(fs::exists(dir / "gone"));
  fs::remove_all(dir);
}

// A file a scenario names was read whatever it was: a pipe blocked `check` for good, /dev/zero
// grew it without end.
TEST(HostileInput, ANamedPipeIsRefusedUnopened) {
  for (const std::string& key : kNamedFileKeys) {
    SCOPED_TRACE(key);
    const fs::path dir = fresh_folder("pipe");
    fs::create_directories(dir);
    const fs::path pipe = dir / "named.pipe";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    const auto result = check_guarded(scenario_naming(dir, key, pipe));
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(key + ": " + pipe.string() + " is not a regular file"), std::string::npos)
        << result.output;
    fs::remove_all(dir);
  }
}

TEST(HostileInput, ANamedDeviceIsRefusedUnread) {
  for (const std::string& key : kNamedFileKeys) {
    SCOPED_TRACE(key);
    const fs::path dir = fresh_folder("device");
    fs::create_directories(dir);
    const auto result = check_guarded(scenario_naming(dir, key, "/dev/zero"));
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(key + ": /dev/zero is not a regular file"), std::string::npos) << result.output;
    fs::remove_all(dir);
  }
}

TEST(HostileInput, ANamedFileBeyondItsKeysSizeIsRefusedUnread) {
  const std::vector<std::pair<std::string, std::uintmax_t>> caps = {{"geometry.fractures_file", 64}, {"mesh.file", 1024}};
  for (const auto& [key, mebibytes] : caps) {
    SCOPED_TRACE(key);
    const fs::path dir = fresh_folder("large");
    fs::create_directories(dir);
    const fs::path large = dir / "large.dat";
    std::ofstream(large) << "x1,y1,x2,y2\n";
    fs::resize_file(large, (mebibytes << 20) + 1);  // a sparse tail of zeros
    const auto result = check_guarded(scenario_naming(dir, key, large));
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(key + ": " + large.string() + " is larger than " + std::to_string(mebibytes) + " MiB"),
              std::string::npos)
        << result.output;
    fs::remove_all(dir);
  }
}

// A sweep's --set with an index that is not a number printed "error: stoul" and exited 1; a
// number beyond what TOML holds was called a string.
TEST(HostileInput, ASetsBadIndexOrOutOfRangeValueIsNamed) {
  const fs::path out = fresh_folder("sweep-set");
  const std::string sweep = "sweep " + kLoadedBlock.string() + " -o " + out.string();
  const auto index = run_program(sweep + " --set 'flow.boundary[x].head=1,2'");
  EXPECT_EQ(index.exit_code, 2) << index.output;
  EXPECT_NE(index.output.find("flow.boundary[x].head: 'boundary[x]' is not a key with array indices"), std::string::npos)
      << index.output;
  const auto range = run_program(sweep + " --set mechanics.steps=1180591620717411303424,3e400");
  EXPECT_EQ(range.exit_code, 2) << range.output;
  for (const std::string value : {"1180591620717411303424", "3e400"})
    EXPECT_NE(range.output.find("--set mechanics.steps=" + value + ": mechanics.steps: " + value + " is out of range"),
              std::string::npos)
        << range.output;
  EXPECT_EQ(range.output.find("got a string"), std::string::npos) << range.output;
  EXPECT_FALSE(fs::exists(out));
}
