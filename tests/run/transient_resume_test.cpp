// A transient flow-only run stopped and resumed from its checkpoint (checkpoint.bin, written at
// each output time and when a stop request ends the run) reaches the same files as a run never
// stopped, byte for byte: history.csv (the steps that factored their matrix included),
// probes.csv, fluid.pvd and every fluid_NNNN.vtu, and summary.json apart from its timings. An
// exact identity: the resumed steps are the same floating-point operations on the same heads.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../cli/run_folder_compare.hpp"
#include "output/checkpoint.hpp"
#include "run/run.hpp"
#include "run/transient_model.hpp"
#include "scenario/overrides.hpp"
#include "scenario/reader.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::expect_same_results;
using hydrodda::testing::read_file;
namespace output = hydrodda::output;
namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;

namespace {

const fs::path kDiffusion = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/transient_diffusion_1d.toml";

struct Folder {
  fs::path path;
  explicit Folder(const std::string& name)
      : path(fs::temp_directory_path() / ("hydrodda-transient-resume-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
  }
  ~Folder() { fs::remove_all(path); }
};

// The 1D diffusion strip on a coarser mesh, no figures: 1,021 steps, outputs at 20, 100, 300
// and 1000 s.
struct Strip {
  std::string text = scenario::apply_overrides(read_file(kDiffusion), kDiffusion,
                                               {{"mesh.size", "0.5"}, {"output.figures", "[]"}});
  scenario::Scenario s = scenario::parse_scenario(text, kDiffusion);
  run::RunOptions options(const fs::path& folder) const { return {folder, false, std::nullopt, text}; }
};

// The run stopped at its `stop_at`-th stop check (before step stop_at), then resumed to the end.
run::RunResult stop_and_resume(const Strip& strip, const fs::path& folder, int stop_at, int& steps_before_stop) {
  int asked = 0;
  run::Callbacks stop;
  stop.stop_requested = [&] { return ++asked == stop_at; };
  const run::RunResult stopped = run::run(strip.s, strip.options(folder), stop);
  EXPECT_EQ(stopped.status, run::RunStatus::interrupted) << stopped.message;
  EXPECT_TRUE(stopped.good_state_kept);
  steps_before_stop = stopped.iterations;
  const run::ResumedRun resumed = run::open_resumed_run(folder);
  EXPECT_TRUE(resumed.transient.has_value());
  if (resumed.transient) {
    EXPECT_EQ(resumed.transient->steps, stopped.iterations);
  }
  return run::resume(resumed, std::nullopt);
}

TEST(TransientResume, AStopMidwayBetweenOutputTimesThenResumeGivesTheSameFilesAsARunNeverStopped) {
  const Strip strip;
  Folder whole("whole"), parts("parts");
  const run::RunResult uninterrupted = run::run(strip.s, strip.options(whole.path));
  ASSERT_EQ(uninterrupted.status, run::RunStatus::finished) << uninterrupted.message;
  int before = 0;
  const run::RunResult continued = stop_and_resume(strip, parts.path, 350, before);
  EXPECT_EQ(before, 349);  // between the outputs at 300 s (step 324) and 1000 s
  ASSERT_EQ(continued.status, run::RunStatus::finished) << continued.message;
  EXPECT_EQ(continued.iterations, uninterrupted.iterations);
  expect_same_results(whole.path, parts.path);
}

TEST(TransientResume, StoppedTwiceOnceRightAfterAnOutputTimeTheResumedRunIsStillTheSame) {
  // Steps 0.01 s growing by 1.2 to 1 s: the output at 20 s ends a step in the first hundred. A
  // stop at the check after it resumes from the checkpoint that output time wrote.
  const Strip strip;
  const std::vector<double> times = run::plan_step_times(*strip.s.flow->transient);
  const int output_step = static_cast<int>(std::find(times.begin(), times.end(), 20.0) - times.begin()) + 1;
  ASSERT_LT(output_step, static_cast<int>(times.size()));
  Folder whole("whole-2"), parts("parts-2");
  ASSERT_EQ(run::run(strip.s, strip.options(whole.path)).status, run::RunStatus::finished);
  int asked = 0;
  run::Callbacks stop;
  stop.stop_requested = [&] { return ++asked == output_step + 1; };
  ASSERT_EQ(run::run(strip.s, strip.options(parts.path), stop).status, run::RunStatus::interrupted);
  // Resumed, and stopped again 100 steps on, then resumed to the end.
  asked = 0;
  stop.stop_requested = [&] { return ++asked == 101; };
  const run::RunResult second = run::resume(run::open_resumed_run(parts.path), std::nullopt, stop);
  ASSERT_EQ(second.status, run::RunStatus::interrupted) << second.message;
  EXPECT_EQ(second.iterations, output_step + 100);
  const run::RunResult last = run::resume(run::open_resumed_run(parts.path), std::nullopt);
  ASSERT_EQ(last.status, run::RunStatus::finished) << last.message;
  expect_same_results(whole.path, parts.path);
}

TEST(TransientResume, ARunThatReachedItsEndTimeIsNotResumed) {
  const Strip strip;
  Folder folder("ended");
  ASSERT_EQ(run::run(strip.s, strip.options(folder.path)).status, run::RunStatus::finished);
  try {
    run::open_resumed_run(folder.path);
    ADD_FAILURE() << "a finished transient run was resumed";
  } catch (const run::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("already reached its end_time (1000 s)"), std::string::npos) << e.what();
  }
}

TEST(TransientResume, TheCheckpointRoundTripsAndADamagedOneIsRefused) {
  output::TransientCheckpoint c;
  c.scenario_hash = 42;
  c.scenario_file = "/a/b.toml";
  c.input_files = {{"mesh.file", "/a/m.msh", 7}};
  c.steps = 3;
  c.time = 2.5;
  c.time_step = 0.75;
  c.history = {{"0", "0"}, {"1", "1.25"}};
  c.probes = {{"0", "p", "1", "2"}};
  c.output_times = {0.0, 2.5};
  c.times = {0.0, 1.25};
  c.storage_rates = {0.0, -1e-9};
  c.boundary_flows = {{0.0, 1.5}, {0.0, -1.5}};
  c.probe_pressures = {{1.0, 2.0}};
  c.state.head = {1.0, 2.0, 3.0};
  c.state.pressure = {4.0, 5.0, 6.0};
  c.state.flux = {{0.1, 0.2}};
  c.state.boundary_flows = {{"left", 1.5}, {"right", -1.5}};
  c.state.storage_rate = -1e-9;
  c.state.balance_error = 1e-15;
  const std::string bytes = output::encode_transient_checkpoint(c);
  EXPECT_TRUE(output::is_transient_checkpoint(bytes));
  const output::TransientCheckpoint back = output::decode_transient_checkpoint(bytes);
  EXPECT_EQ(output::encode_transient_checkpoint(back), bytes);  // every field read back as written
  EXPECT_EQ(back.state.head, c.state.head);
  EXPECT_EQ(back.state.boundary_flows[1].name, "right");
  EXPECT_EQ(back.probe_pressures, c.probe_pressures);
  std::string damaged = bytes;
  damaged[damaged.size() / 2] ^= 0x10;
  EXPECT_THROW(output::decode_transient_checkpoint(damaged), output::CheckpointError);
  EXPECT_THROW(output::decode_transient_checkpoint(bytes.substr(0, bytes.size() - 3)), output::CheckpointError);
  EXPECT_THROW(output::decode_checkpoint(bytes), output::CheckpointError);  // not a coupled run's
}

}  // namespace
