// Settling passes (coupling.settle) on blocks that drift rather than settle, through the program.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_program.hpp"

namespace fs = std::filesystem;
using namespace hydrodda::testing;

namespace {

// The seal of tests/cli/scenarios/open_seal_settling.toml: 4 joints and 3 beds 2 mm open, base
// and sides held, 30 m of head, settling passes of 20 steps of 1 ms. Its free blocks fall a few
// µm a step, not slowing, and every row but the lowest falls with the row under it, their
// joints closing by nothing: no row above the lowest lands within the 2,000 settle steps (the
// whole seal would need some 800 steps a row). Each pass ends once 20 steps in a row have had
// such a block (coupling/settling_watch.hpp), not at rest, where it stepped on 2,020 times:
// history.csv's time grows by 20 to 40 steps of 1 ms a pass (measured 28 and 21: the first
// steps of a pass judge no block slowing until its second step, and the side blocks slowing
// onto their supports, or meeting nothing, hold the count back for a few). The warning names a
// drifting block, and the loop does not call the pass converged.
TEST(CoupledRun, ASettlingPassStopsWhenItsBlocksDriftWithNothingToLandOn) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/open_seal_settling.toml";
  const fs::path out = fs::temp_directory_path() / ("hydrodda-open-seal-settling-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const ProgramResult result = run_program("-q run --threads 1 " + scenario.string() + " -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto history = read_csv(out / "history.csv");
  ASSERT_EQ(history.size(), 3u);  // header and two passes
  const auto& header = history[0];
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(column("at_rest"), header.size());
  double last_time = 0.0;
  for (std::size_t row = 1; row < history.size(); ++row) {
    const double time = std::stod(history[row][column("time")]);
    EXPECT_GE(time - last_time, 0.020 - 1e-9) << "pass " << row << " ran its 20 steps";
    EXPECT_LE(time - last_time, 0.040 + 1e-9) << "pass " << row << " stopped drifting, not at its 2,020 steps";
    EXPECT_EQ(history[row][column("at_rest")], "0") << "pass " << row;
    last_time = time;
  }
  EXPECT_NE(result.output.find("moving freely, not slowing, and at its steps' rate landing only after the settle steps left"),
            std::string::npos)
      << result.output;
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["converged"], false);
  fs::remove_all(out);
}

}  // namespace
