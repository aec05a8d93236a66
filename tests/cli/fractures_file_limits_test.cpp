// A fractures file past what can be cut into blocks is refused by `check`, before any cutting:
// too many rows, or traces that would cross into too many blocks.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::run_program;

namespace {

// A folder with case.toml reading dfn.csv, whose rows `write_rows` writes.
template <class WriteRows>
fs::path scenario_with_fractures_file(const std::string& name, WriteRows&& write_rows) {
  const fs::path dir = fs::temp_directory_path() / ("hydrodda-fractures-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << "[geometry]\n"
                                      "domain = [[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]]\n"
                                      "fractures_file = \"dfn.csv\"\n"
                                      "[material.rock]\ndensity = 2500.0\nyoung = 1.0e10\npoisson = 0.25\n"
                                      "[mechanics]\nanalysis = \"dynamic\"\nsteps = 10\n";
  std::ofstream rows(dir / "dfn.csv");
  rows << "x1,y1,x2,y2\n";
  write_rows(rows);
  return dir;
}

}  // namespace

TEST(FracturesFileLimits, MoreRowsThanCanBeCutAreRefused) {
  // 100,001 short traces, a metre apart, that cross nothing.
  const fs::path dir = scenario_with_fractures_file("rows", [](std::ofstream& rows) {
    for (int k = 0; k <= 100'000; ++k) rows << 1 + k % 98 << ',' << 0.5 + 0.0009 * (k / 98) << ',' << 1.5 + k % 98 << ','
                                            << 0.5 + 0.0009 * (k / 98) << '\n';
  });
  const auto result = run_program("check " + (dir / "case.toml").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("case.toml:3: geometry.fractures_file: " + (dir / "dfn.csv").string() +
                               " holds 100001 traces; at most 100000 can be cut into blocks"),
            std::string::npos)
      << result.output;
  fs::remove_all(dir);
}

TEST(FracturesFileLimits, TracesThatWouldMakeTooManyBlocksAreRefused) {
  // 1,200 traces across the square each way, 8 cm apart: some 1.4 million crossings, blocks.
  const fs::path dir = scenario_with_fractures_file("blocks", [](std::ofstream& rows) {
    for (int k = 1; k <= 1200; ++k) rows << "0," << 0.083 * k << ",100," << 0.083 * k << '\n' << 0.083 * k << ",0," << 0.083 * k << ",100\n";
  });
  const auto result = run_program("check " + (dir / "case.toml").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("case.toml:3: geometry.fractures_file: the 2400 traces of " + (dir / "dfn.csv").string() +
                               " would cut the domain into some 1.4e+06 blocks"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("at most 1e+06 can be made"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("1 error(s)"), std::string::npos) << result.output;

  // 100 each way, 99 cm apart: some 10,000 blocks, accepted and cut.
  const fs::path fewer = scenario_with_fractures_file("fewer", [](std::ofstream& rows) {
    for (int k = 1; k <= 100; ++k) rows << "0," << 0.99 * k << ",100," << 0.99 * k << '\n' << 0.99 * k << ",0," << 0.99 * k << ",100\n";
  });
  const auto accepted = run_program("check " + (fewer / "case.toml").string());
  EXPECT_EQ(accepted.exit_code, 0) << accepted.output;
  EXPECT_NE(accepted.output.find("200 traces (200 from dfn.csv), 10201 blocks"), std::string::npos) << accepted.output;
  fs::remove_all(dir);
  fs::remove_all(fewer);
}
