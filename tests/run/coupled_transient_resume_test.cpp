// A coupled transient run stopped and resumed from its checkpoint (checkpoint.bin, written at
// t = 0, at each output time, when a stop request or --stop-after ends the run, and at its end)
// reaches the same files as a run never stopped, byte for byte: history.csv, probes.csv,
// measure.csv, fractures.csv, every .pvd and .vtu, the checkpoint, and summary.json apart from
// its timings. An exact identity: the resumed steps are the same floating-point operations on the
// same blocks and heads (the DDA system restarts its solver from its exported state after every
// pass in both runs; the flow factors again from the same values).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../cli/run_folder_compare.hpp"
#include "../cli/result_files.hpp"
#include "output/checkpoint.hpp"
#include "run/run.hpp"
#include "scenario/overrides.hpp"
#include "scenario/reader.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::expect_same_results;
using hydrodda::testing::read_file;
namespace output = hydrodda::output;
namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;

namespace {

const fs::path kColumn = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/terzaghi_consolidation.toml";


// Terzaghi's column of twenty blocks as shipped, no figures: 54 steps to 1.4e5 s, outputs at
// 4,667, 9,333, 28,000 and 93,330 s (steps 19, 23, 30 and 44).
struct Column {
  std::string text = scenario::apply_overrides(read_file(kColumn), kColumn, {{"output.figures", "[]"}});
  scenario::Scenario s = scenario::parse_scenario(text, kColumn);
  run::RunOptions options(const fs::path& folder) const { return {folder, false, std::nullopt, text}; }
};

// The uninterrupted run, once for every test.
const fs::path& whole_run() {
  static const auto folder = hydrodda::testing::fresh_dir("hydrodda-coupled-transient-resume-whole");
  static const bool ran = [] {
    const Column column;
    const run::RunResult r = run::run(column.s, column.options(folder.path));
    EXPECT_EQ(r.status, run::RunStatus::finished) << r.message;
    EXPECT_TRUE(r.converged);
    return true;
  }();
  (void)ran;
  return folder.path;
}

TEST(CoupledTransientResume, AnInterruptMidStepThenResumeGivesTheFilesOfARunNeverStopped) {
  const Column column;
  const auto parts = hydrodda::testing::fresh_dir("hydrodda-coupled-transient-resume-interrupted");
  // Stop checks come before every pass, DDA step and open–close pass: the 1,450th falls within
  // a step between the outputs at 4,667 s and 9,333 s, which is abandoned, the model back at the
  // last step's end.
  int asked = 0;
  run::Callbacks stop;
  stop.stop_requested = [&] { return ++asked == 1450; };
  const run::RunResult stopped = run::run(column.s, column.options(parts.path), stop);
  ASSERT_EQ(stopped.status, run::RunStatus::interrupted) << stopped.message;
  EXPECT_TRUE(stopped.good_state_kept);
  const run::ResumedRun resumed = run::open_resumed_run(parts.path);
  ASSERT_TRUE(resumed.coupled_transient.has_value());
  EXPECT_EQ(resumed.coupled_transient->steps, stopped.iterations);
  EXPECT_FALSE(resumed.coupled_transient->ended);
  EXPECT_GT(resumed.coupled_transient->time, 4667.0);
  EXPECT_LT(resumed.coupled_transient->time, 9333.0);
  const run::RunResult rest = run::resume(resumed, std::nullopt);
  ASSERT_EQ(rest.status, run::RunStatus::finished) << rest.message;
  EXPECT_TRUE(rest.converged);
  expect_same_results(whole_run(), parts.path);
}

TEST(CoupledTransientResume, ResumedFromTheCheckpointOfItsFirstOutputTimeAsAKilledRunLeavesIt) {
  // The checkpoint the first output time wrote (step 19), kept aside; the run then stopped five
  // steps on, past the next output time, and its checkpoint replaced by that one (what a run
  // killed by SIGKILL there leaves): the resumed run rewrites history.csv and the tables from the
  // checkpoint's rows, keeps fractures.csv's up to its step, and runs the steps after it again,
  // writing the fields at 9,333 s anew.
  const Column column;
  const auto parts = hydrodda::testing::fresh_dir("hydrodda-coupled-transient-resume-killed");
  const fs::path kept = parts.path.string() + "-first-output.bin";
  int steps = 0;
  run::Callbacks callbacks;
  callbacks.progress = [&](const run::ProgressReport& r) {
    if (r.time == 4667.0) fs::copy_file(parts.path / "checkpoint.bin", kept, fs::copy_options::overwrite_existing);
    steps = static_cast<int>(r.count);
  };
  callbacks.stop_requested = [&] { return fs::exists(kept) && steps == 24; };
  ASSERT_EQ(run::run(column.s, column.options(parts.path), callbacks).status, run::RunStatus::interrupted);
  ASSERT_TRUE(fs::exists(kept));
  fs::copy_file(kept, parts.path / "checkpoint.bin", fs::copy_options::overwrite_existing);
  fs::remove(kept);
  const run::ResumedRun resumed = run::open_resumed_run(parts.path);
  ASSERT_TRUE(resumed.coupled_transient.has_value());
  EXPECT_EQ(resumed.coupled_transient->time, 4667.0);
  EXPECT_EQ(resumed.coupled_transient->output_times, (std::vector<double>{0.0, 4667.0}));
  const run::RunResult rest = run::resume(resumed, std::nullopt);
  ASSERT_EQ(rest.status, run::RunStatus::finished) << rest.message;
  expect_same_results(whole_run(), parts.path);
}

TEST(CoupledTransientResume, StoppedAfterAStepTwiceThenResumedToTheEndIsStillTheSame) {
  const Column column;
  const auto parts = hydrodda::testing::fresh_dir("hydrodda-coupled-transient-resume-stop-after");
  run::RunOptions options = column.options(parts.path);
  options.stop_after = 3;
  const run::RunResult first = run::run(column.s, options);
  ASSERT_EQ(first.status, run::RunStatus::stopped) << first.message;
  EXPECT_EQ(first.iterations, 3);
  EXPECT_NE(first.message.find("stopped after time step 3"), std::string::npos) << first.message;
  const run::RunResult second = run::resume(run::open_resumed_run(parts.path), 30);
  ASSERT_EQ(second.status, run::RunStatus::stopped) << second.message;
  EXPECT_EQ(second.iterations, 30);
  const run::RunResult last = run::resume(run::open_resumed_run(parts.path), std::nullopt);
  ASSERT_EQ(last.status, run::RunStatus::finished) << last.message;
  expect_same_results(whole_run(), parts.path);
  // Ended, and its summary.json says so: nothing to resume.
  try {
    run::open_resumed_run(parts.path);
    ADD_FAILURE() << "a finished coupled transient run was resumed";
  } catch (const run::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("already reached its end_time (140000 s)"), std::string::npos) << e.what();
  }
}

TEST(CoupledTransientResume, ARunThatEndedNotConvergedAtItsFloorIsNotResumed) {
  // coupling.max_iterations = 3 against the ~13 the column's first step needs: that step is cut
  // to its floor and the run ends not converged at t = 0 (CoupledTransientVerification.*); its
  // checkpoint says it ended, and its summary.json says so too.
  const Column column;
  const std::string text = scenario::apply_overrides(column.text, kColumn, {{"coupling.max_iterations", "3"}});
  const scenario::Scenario s = scenario::parse_scenario(text, kColumn);
  const auto folder = hydrodda::testing::fresh_dir("hydrodda-coupled-transient-resume-floor");
  const run::RunResult r = run::run(s, {folder.path, false, std::nullopt, text});
  ASSERT_EQ(r.status, run::RunStatus::finished) << r.message;
  ASSERT_FALSE(r.converged);
  try {
    run::open_resumed_run(folder.path);
    ADD_FAILURE() << "a coupled transient run that ended not converged was resumed";
  } catch (const run::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ended not converged at t = 0 s"), std::string::npos) << e.what();
  }
}

output::CoupledTransientCheckpoint small_checkpoint() {
  output::CoupledTransientCheckpoint c;
  c.scenario_hash = 42;
  c.scenario_file = "/a/b.toml";
  c.input_files = {{"mesh.file", "/a/m.msh", 7}};
  c.steps = 3;
  c.time = 2.5;
  c.nominal_step = 0.75;
  c.next_stop = 1;
  c.history = {{"0", "0"}, {"1", "1.25"}};
  c.probes = {{"0", "p", "1", "2"}};
  c.measure = {{"0", "0", "top", "0.5", "10", "0", "0"}};
  c.output_times = {0.0, 2.5};
  c.times = {0.0, 1.25};
  c.storage_rates = {0.0, -1e-9};
  c.boundary_flows = {{0.0, 1.5}};
  c.probe_pressures = {{1.0, 2.0}};
  c.fracture_counts = {0, 0, 0, 0, 0, 1, 2, 0.5, 1e-4, 2e-4};
  c.mechanics.time = 3.0;
  c.mechanics.time_step = 1.0;
  c.coupling.iterations = 12;
  c.coupling.flow.head = {1.0, 2.0, 3.0};
  c.coupling.flow.boundary_flows = {{"top", 1.5}};
  c.coupling.flow.storage_rate = -1e-9;
  c.coupling.previous_heads = {1.0, 2.0, 3.0};
  return c;
}

TEST(CoupledTransientResume, TheCheckpointRoundTripsAndADamagedOrOtherOneIsRefused) {
  const output::CoupledTransientCheckpoint c = small_checkpoint();
  const std::string bytes = output::encode_coupled_transient_checkpoint(c);
  EXPECT_TRUE(output::is_coupled_transient_checkpoint(bytes));
  EXPECT_FALSE(output::is_transient_checkpoint(bytes));
  const output::CoupledTransientCheckpoint back = output::decode_coupled_transient_checkpoint(bytes);
  EXPECT_EQ(output::encode_coupled_transient_checkpoint(back), bytes);  // every field read back as written
  EXPECT_EQ(back.coupling.flow.storage_rate, -1e-9);
  EXPECT_EQ(back.fracture_counts, c.fracture_counts);
  EXPECT_EQ(back.next_stop, 1);
  std::string damaged = bytes;
  damaged[damaged.size() / 2] ^= 0x10;
  EXPECT_THROW(output::decode_coupled_transient_checkpoint(damaged), output::CheckpointError);
  EXPECT_THROW(output::decode_coupled_transient_checkpoint(bytes.substr(0, bytes.size() - 3)), output::CheckpointError);
  EXPECT_THROW(output::decode_checkpoint(bytes), output::CheckpointError);            // not a steady run's
  EXPECT_THROW(output::decode_transient_checkpoint(bytes), output::CheckpointError);  // nor a flow-only one's
}

TEST(CoupledTransientResume, ACheckpointOfAnotherFormatIsRefusedNamingBoth) {
  // The format number follows the magic line: format 0 stands for any other than this one.
  std::string bytes = output::encode_coupled_transient_checkpoint(small_checkpoint());
  const std::size_t at = std::string("hydrodda coupled transient checkpoint\n").size();
  const std::int64_t other = 0;
  bytes.replace(at, sizeof other, reinterpret_cast<const char*>(&other), sizeof other);
  try {
    output::decode_coupled_transient_checkpoint(bytes);
    ADD_FAILURE() << "a checkpoint of another format was read";
  } catch (const output::CheckpointError& e) {
    EXPECT_EQ(std::string(e.what()), "coupled transient checkpoint format 0; this hydrodda reads format 5");
  }
}

}  // namespace
