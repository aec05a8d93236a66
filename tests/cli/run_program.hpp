#pragma once
// Runs the real hydrodda program and captures what it prints, for command-line tests.

#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace hydrodda::testing {

struct ProgramResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Any shell command, with stderr folded into the output.
inline ProgramResult run_command(const std::string& shell_command) {
  const std::string command = shell_command + " 2>&1";
  ProgramResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// A scratch folder of the running test, named after it and the process (for ctest -j), empty.
inline std::filesystem::path scratch_folder() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("hydrodda-" + std::string(test->name()) + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline ProgramResult run_program(const std::string& arguments) {
  return run_command(std::string(HYDRODDA_BINARY) + " " + arguments);
}

// A scenario file with each `from` text replaced once by its `to` (a missing one fails the
// test), written to the temporary folder as NAME.toml.
inline std::filesystem::path edited_scenario(const std::filesystem::path& original, const std::string& name,
                                             const std::vector<std::pair<std::string, std::string>>& edits) {
  std::ifstream in(original);
  std::stringstream text;
  text << in.rdbuf();
  std::string scenario = text.str();
  for (const auto& [from, to] : edits) {
    const auto at = scenario.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) scenario.replace(at, from.size(), to);
  }
  const std::filesystem::path file = std::filesystem::temp_directory_path() / (name + ".toml");
  std::ofstream(file) << scenario;
  return file;
}

// Runs a shipped scenario (path relative to the source tree) into a fresh temporary folder and
// returns its summary.json; the test fails if the run does not exit with 0. The folder is named
// after the test and the process as well as the scenario: tests that run the same scenario
// side by side (ctest -j) must not share it.
inline nlohmann::json run_scenario_and_read(const std::string& relative_path) {
  namespace fs = std::filesystem;
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / relative_path;
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path out = fs::temp_directory_path() /
                       ("hydrodda-" + std::string(test ? test->name() : "test") + "-" + std::to_string(::getpid()) +
                        "-" + scenario.stem().string());
  fs::remove_all(out);
  const ProgramResult result = run_program("run " + scenario.string() + " -o " + out.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  std::ifstream in(out / "summary.json");
  nlohmann::json summary = in ? nlohmann::json::parse(in) : nlohmann::json::object();
  fs::remove_all(out);
  return summary;
}

// Rows of a CSV file; a cell in double quotes may hold commas, and "" inside it is one quote
// (RFC 4180, as output::CsvTable writes it). A trailing empty cell is kept.
inline std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        cells.emplace_back();
      } else {
        cells.back() += c;
      }
    }
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace hydrodda::testing
