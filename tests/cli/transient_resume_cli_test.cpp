// A transient flow-only run interrupted by Ctrl-C (held at its 350th stop check, before step
// 350 of 1,021, between output times: cli/hold_points.hpp, no delay) exits with 1 saying where
// it stopped; `run --resume` continues it from the checkpoint of its last finished step to the
// files of a run never stopped, byte for byte (summary.json apart from its timings), and a
// second `run --resume` of the finished run is refused with exit code 2.

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

TEST(TransientResumeCli, AnInterruptedTransientRunResumesToTheFilesOfOneNeverStopped) {
  const auto dir = fresh_dir("hydrodda-transient-resume-cli");
  fs::create_directories(dir.path);
  // The shipped strip on a coarser mesh (its 1,021 steps unchanged), no figures.
  const fs::path scenario = hydrodda::testing::edited_scenario(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/transient_diffusion_1d.toml",
      "hydrodda-transient-resume-cli-" + std::to_string(::getpid()),
      {{"size = 0.1\n", "size = 0.5\n"}, {"figures = [\"png\"]\n", "figures = []\n"}});
  const fs::path whole = dir.path / "whole", parts = dir.path / "parts";
  const auto uninterrupted = run_program("run " + scenario.string() + " -o " + whole.string() + " --threads 1");
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.output;

  const auto interrupted = hydrodda::testing::interrupt_at_stop_check(scenario, parts, 350);
  EXPECT_EQ(interrupted.exit_code, 1) << interrupted.output;
  EXPECT_NE(interrupted.output.find("interrupted at t = 328 s, after 349 of 1021 steps"), std::string::npos) << interrupted.output;
  const nlohmann::json stopped = nlohmann::json::parse(std::ifstream(parts / "summary.json"));
  EXPECT_EQ(stopped["status"], "interrupted");
  EXPECT_EQ(stopped["iterations"], 349);

  hydrodda::testing::expect_resumes_to(parts, whole, "already reached its end_time");
  fs::remove(scenario);
}
