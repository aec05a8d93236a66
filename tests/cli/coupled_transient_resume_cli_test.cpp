// A coupled transient run interrupted by Ctrl-C (held at its 800th stop check, within a step
// between the output times at 4,667 s and 9,333 s: cli/hold_points.hpp, no delay) exits with 1
// saying where it stopped; `run --resume` continues it from the checkpoint of its last finished
// step to the files of a run never stopped, byte for byte (summary.json apart from its timings),
// and a second `run --resume` of the finished run is refused with exit code 2.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "interrupted_run.hpp"
#include "result_files.hpp"
#include "run_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::fresh_dir;
using hydrodda::testing::run_program;

TEST(CoupledTransientResumeCli, AnInterruptedCoupledTransientRunResumesToTheFilesOfOneNeverStopped) {
  const auto dir = fresh_dir("hydrodda-coupled-transient-resume-cli");
  fs::create_directories(dir.path);
  // Terzaghi's column as shipped (54 steps), no figures.
  const fs::path scenario = hydrodda::testing::edited_scenario(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/terzaghi_consolidation.toml",
      "hydrodda-coupled-transient-resume-cli-" + std::to_string(::getpid()), {{"figures = [\"png\"]\n", "figures = []\n"}});
  const fs::path whole = dir.path / "whole", parts = dir.path / "parts";
  const auto uninterrupted = run_program("run " + scenario.string() + " -o " + whole.string() + " --threads 1");
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.output;

  const auto interrupted = hydrodda::testing::interrupt_at_stop_check(scenario, parts, 1450);
  EXPECT_EQ(interrupted.exit_code, 1) << interrupted.output;
  EXPECT_NE(interrupted.output.find("interrupted at t = 6700.73 s, after 21 steps"), std::string::npos) << interrupted.output;
  const nlohmann::json stopped = nlohmann::json::parse(std::ifstream(parts / "summary.json"));
  EXPECT_EQ(stopped["status"], "interrupted");
  EXPECT_GT(stopped["time"].get<double>(), 4667.0);
  EXPECT_LT(stopped["time"].get<double>(), 9333.0);

  hydrodda::testing::expect_resumes_to(parts, whole, "already reached its end_time");
  fs::remove(scenario);
}
