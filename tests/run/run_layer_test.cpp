// The run layer called directly, in this process: a flow-only, a mechanics-only and a coupled
// run of small shipped verification scenarios against the analytic values their files state,
// a stop request honoured between coupling passes, and a coupled model stepped by hand.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../cli/run_folder_compare.hpp"
#include "../cli/run_program.hpp"
#include "output/checkpoint.hpp"
#include "run/coupled_model.hpp"
#include "run/figures.hpp"
#include "run/model_building.hpp"
#include "run/run.hpp"
#include "scenario/overrides.hpp"
#include "scenario/reader.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::expect_same_results;
using hydrodda::testing::read_file;
namespace coupling = hydrodda::coupling;
namespace run = hydrodda::run;
namespace scenario = hydrodda::scenario;

namespace {

const fs::path kVerification = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification";
constexpr double kG = 9.81;
constexpr double kRhoWater = 1000.0;
constexpr double kRhoRock = 2500.0;

// A run folder of its own for each test and process (ctest runs tests side by side); removed
// at the end.
struct Folder {
  fs::path path;
  explicit Folder(const std::string& name)
      : path(fs::temp_directory_path() / ("hydrodda-run-layer-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
  }
  ~Folder() { fs::remove_all(path); }
};

// The progress reports of a run, and a stop request after `stop_after_reports` of them (never
// when negative).
struct Recorder {
  std::vector<run::ProgressReport> reports;
  int stop_after_reports = -1;
  run::Callbacks callbacks() {
    run::Callbacks callbacks;
    callbacks.progress = [this](const run::ProgressReport& r) { reports.push_back(r); };
    callbacks.stop_requested = [this] {
      return stop_after_reports >= 0 && static_cast<int>(reports.size()) >= stop_after_reports;
    };
    return callbacks;
  }
};

double boundary_flow(const hydrodda::output::RunSummary& summary, const std::string& name) {
  for (const auto& b : summary.flow->boundaries)
    if (b.name == name) return b.value;
  ADD_FAILURE() << "no boundary " << name;
  return NAN;
}

std::size_t count_lines(const fs::path& file) {
  std::ifstream in(file);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

// The column settles elastically (coupled_hydrostatic_column.toml): with the dry column's
//   s_dry(y) = rho_r g (H y - y^2 / 2) / E',  E' = E / (1 - nu^2),  H = 3 m (plane strain),
// block k's settlement (at its centroid, y = k + 1/2) lies between the effective-stress value
// (rho_r - rho_w) / rho_r * s_dry(y) and s_dry(y) + k * 1.5e-6 m (k contacts below it, each
// allowed to penetrate 1e-4 of the allowed step displacement), and no block moves sideways
// (under 1e-7 m).
void expect_column_settled(const hydrodda::output::RunSummary& s) {
  const double e_plane = 1.0e10 / (1.0 - 0.25 * 0.25), height = 3.0;
  const auto s_dry = [&](double y) { return kRhoRock * kG * (height * y - 0.5 * y * y) / e_plane; };
  const double effective = (kRhoRock - kRhoWater) / kRhoRock;
  const double penetration = 1e-4 * 0.01 * 0.5 * height;
  ASSERT_EQ(s.blocks.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const double settlement = -s.blocks[k].displacement[1], y = k + 0.5;
    EXPECT_LT(std::abs(s.blocks[k].displacement[0]), 1e-7) << "block " << k;
    EXPECT_GE(settlement, effective * s_dry(y)) << "block " << k;
    EXPECT_LE(settlement, s_dry(y) + k * penetration) << "block " << k;
  }
}

TEST(RunLayer, FlowOnlyRunOfLayersInSeriesGivesTheHarmonicMean) {
  // flow_layers_series.toml: Q = dh / sum(L_i / K_i) = 1.961018510e-05 m2/s through the unit
  // square, in on the left and out on the right, within 1e-8 relative (P1 is exact for a head
  // linear in each layer; the rest is round-off and the ten digits of the stated value).
  const scenario::Scenario s = scenario::read_scenario(kVerification / "flow_layers_series.toml");
  Folder folder("flow");
  Recorder recorder;
  const run::RunResult result = run::run(s, {folder.path}, recorder.callbacks());

  EXPECT_EQ(result.status, run::RunStatus::finished);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 1);
  EXPECT_TRUE(result.message.empty());
  EXPECT_EQ(result.folder, folder.path);
  const double exact = 1.961018510e-05;
  ASSERT_TRUE(result.summary.flow);
  EXPECT_NEAR(boundary_flow(result.summary, "left"), -exact, 1e-8 * exact);
  EXPECT_NEAR(boundary_flow(result.summary, "right"), exact, 1e-8 * exact);
  EXPECT_LT(result.summary.flow->balance, 1e-12);

  ASSERT_EQ(recorder.reports.size(), 1u);
  EXPECT_EQ(recorder.reports[0].kind, run::ProgressReport::Kind::flow_solve);
  EXPECT_EQ(recorder.reports[0].balance_error, result.summary.flow->balance);
  EXPECT_NE(recorder.reports[0].message.find("flow solved"), std::string::npos);

  // The folder holds what the result says, and the series of a flow-only run.
  EXPECT_EQ(read_file(folder.path / "summary.json"), hydrodda::output::format_summary(result.summary));
  for (const char* file : {"fluid.pvd", "fluid_0000.vtu", "figures/head.png", "figures/permeability.png"})
    EXPECT_TRUE(fs::exists(folder.path / file)) << file;
  for (const char* file : {"blocks.pvd", "checkpoint.bin", "history.csv"})
    EXPECT_FALSE(fs::exists(folder.path / file)) << file;
}

TEST(RunLayer, MechanicsOnlyRunOfAFreeFallFollowsHalfGTSquared) {
  // free_fall.toml until t = 0.1 s (100 steps of 1 ms; no contact): d(t) = ½ g t² = 0.04905 m.
  // The step's update (d = v Δt + ½ g Δt², v += g Δt) is exact under a constant force, so the
  // tolerance is round-off over 100 steps: 1e-12 relative (measured 4e-16).
  const fs::path file = kVerification / "free_fall.toml";
  const std::string text = scenario::apply_overrides(read_file(file), file, {{"mechanics.end_time", "0.1"}});
  const scenario::Scenario s = scenario::parse_scenario(text, file);
  Folder folder("mechanics");
  Recorder recorder;
  const run::RunResult result = run::run(s, {folder.path, false, std::nullopt, text}, recorder.callbacks());

  EXPECT_EQ(result.status, run::RunStatus::finished);
  EXPECT_TRUE(result.converged);  // mechanics alone: it reached its end
  EXPECT_EQ(result.iterations, 100);
  ASSERT_EQ(result.summary.measures.size(), 1u);
  const double drop = 0.5 * kG * 0.1 * 0.1;
  EXPECT_NEAR(result.summary.measures[0].displacement[1], -drop, 1e-12 * drop);
  EXPECT_NEAR(result.summary.measures[0].displacement[0], 0.0, 1e-12);

  // One report a step, numbered, up to the end time.
  ASSERT_EQ(recorder.reports.size(), 100u);
  for (std::size_t i = 0; i < recorder.reports.size(); ++i) {
    EXPECT_EQ(recorder.reports[i].kind, run::ProgressReport::Kind::mechanics_step);
    EXPECT_EQ(recorder.reports[i].count, static_cast<long long>(i + 1));
  }
  EXPECT_NEAR(recorder.reports.back().time, 0.1, 1e-12);

  EXPECT_EQ(count_lines(folder.path / "history.csv"), 101u);   // header and 100 steps
  EXPECT_EQ(count_lines(folder.path / "measure.csv"), 101u);
  for (const char* f : {"summary.json", "blocks.pvd", "blocks_0000.vtu", "blocks_0100.vtu", "contacts_0100.vtu"})
    EXPECT_TRUE(fs::exists(folder.path / f)) << f;
}

// The .vtu files of a series in the folder, by name, and the files its .pvd lists.
std::vector<std::string> series_files(const fs::path& folder, const std::string& series) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(series + "_") && name.ends_with(".vtu")) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}
std::vector<std::string> listed_in_pvd(const fs::path& pvd) {
  std::vector<std::string> names;
  const std::string text = read_file(pvd);
  for (std::size_t at = text.find("file=\""); at != std::string::npos; at = text.find("file=\"", at + 1)) {
    const std::size_t begin = at + 6;
    names.push_back(text.substr(begin, text.find('"', begin) - begin));
  }
  return names;
}

TEST(RunLayer, FieldsAtTheFirstAndLastStateAndEveryNSteps) {
  // 250 steps of the free fall. By default (every = 100): steps 0, 100, 200 and the last, 250.
  const fs::path file = kVerification / "free_fall.toml";
  const std::string text = scenario::apply_overrides(read_file(file), file, {{"mechanics.end_time", "0.25"}});
  {
    Folder folder("every-default");
    const run::RunResult result = run::run(scenario::parse_scenario(text, file), {folder.path});
    ASSERT_EQ(result.iterations, 250);
    const std::vector<std::string> blocks{"blocks_0000.vtu", "blocks_0100.vtu", "blocks_0200.vtu", "blocks_0250.vtu"};
    EXPECT_EQ(series_files(folder.path, "blocks"), blocks);
    EXPECT_EQ(listed_in_pvd(folder.path / "blocks.pvd"), blocks);
    EXPECT_EQ(series_files(folder.path, "contacts").size(), 4u);
  }
  // every = 60 and only the contacts: steps 0, 60, 120, 180, 240 and 250; no block files.
  {
    Folder folder("every-fields");
    const std::string chosen = text + "\n[output]\nevery = 60\nfields = [\"contacts\"]\n";
    const run::RunResult result = run::run(scenario::parse_scenario(chosen, file), {folder.path});
    ASSERT_EQ(result.status, run::RunStatus::finished);
    const std::vector<std::string> contacts{"contacts_0000.vtu", "contacts_0060.vtu", "contacts_0120.vtu",
                                            "contacts_0180.vtu", "contacts_0240.vtu", "contacts_0250.vtu"};
    EXPECT_EQ(series_files(folder.path, "contacts"), contacts);
    EXPECT_EQ(listed_in_pvd(folder.path / "contacts.pvd"), contacts);
    EXPECT_TRUE(series_files(folder.path, "blocks").empty());
    EXPECT_FALSE(fs::exists(folder.path / "blocks.pvd"));
  }
}

TEST(RunLayer, CoupledRunOfABlockColumnInStillWaterConverges) {
  // coupled_hydrostatic_column.toml: equal heads (3 m) on the bottom and the top, so no flow
  // (under 1e-15 m2/s on both; a 1 mm head difference would drive 3e-12), and the blocks settle
  // elastically under their buoyant weight (expect_column_settled).
  const scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  Folder folder("coupled");
  Recorder recorder;
  const run::RunResult result = run::run(s, {folder.path}, recorder.callbacks());

  EXPECT_EQ(result.status, run::RunStatus::finished);
  EXPECT_TRUE(result.converged);
  ASSERT_GE(result.iterations, 2);  // the first pass never converges (its changes are 1)
  ASSERT_TRUE(result.summary.flow);
  for (const char* boundary : {"bottom", "top"})
    EXPECT_LE(std::abs(boundary_flow(result.summary, boundary)), 1e-15) << boundary;
  expect_column_settled(result.summary);

  // One report a pass, the last one's changes under the tolerance.
  ASSERT_EQ(recorder.reports.size(), static_cast<std::size_t>(result.iterations));
  EXPECT_EQ(recorder.reports.back().kind, run::ProgressReport::Kind::coupling_pass);
  EXPECT_EQ(recorder.reports.back().count, result.iterations);
  EXPECT_LT(recorder.reports.back().displacement_change, s.coupling.tolerance);
  EXPECT_LT(recorder.reports.back().head_change, s.coupling.tolerance);

  EXPECT_EQ(count_lines(folder.path / "history.csv"), static_cast<std::size_t>(result.iterations) + 1);
  EXPECT_EQ(read_file(folder.path / "scenario.toml"), read_file(s.file));
  const auto checkpoint = hydrodda::output::decode_checkpoint(read_file(folder.path / "checkpoint.bin"));
  EXPECT_EQ(checkpoint.coupling.iterations, result.iterations);
  EXPECT_TRUE(checkpoint.converged);
}

TEST(RunLayer, AStopRequestedAfterTheFirstPassLeavesTheFolderAtThatPass) {
  // The stop request turns true once pass 1 has been reported: the run stops before pass 2,
  // says so, and its folder holds pass 1's state, from which it resumes to the same end as a
  // run never stopped, file for file.
  const scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  Folder whole("whole"), parts("parts");
  const run::RunResult uninterrupted = run::run(s, {whole.path});
  ASSERT_EQ(uninterrupted.status, run::RunStatus::finished);
  ASSERT_GE(uninterrupted.iterations, 2);  // so that 1 is mid-run

  Recorder recorder;
  recorder.stop_after_reports = 1;
  const run::RunResult stopped = run::run(s, {parts.path}, recorder.callbacks());
  EXPECT_EQ(stopped.status, run::RunStatus::interrupted);
  EXPECT_FALSE(stopped.converged);
  EXPECT_EQ(stopped.iterations, 1);
  EXPECT_EQ(stopped.message, "interrupted after coupling iteration 1");
  EXPECT_EQ(recorder.reports.size(), 1u);
  EXPECT_EQ(stopped.summary.status, "interrupted");
  EXPECT_EQ(read_file(parts.path / "summary.json"), hydrodda::output::format_summary(stopped.summary));
  EXPECT_EQ(count_lines(parts.path / "history.csv"), 2u);  // header and pass 1
  EXPECT_TRUE(fs::exists(parts.path / "fluid_0001.vtu"));
  EXPECT_FALSE(fs::exists(parts.path / "fluid_0002.vtu"));

  const auto checkpoint = hydrodda::output::decode_checkpoint(read_file(parts.path / "checkpoint.bin"));
  EXPECT_EQ(checkpoint.coupling.iterations, 1);
  EXPECT_FALSE(checkpoint.converged);
  // The summary describes pass 1's state: the model's after one pass.
  run::CoupledModel one_pass(s);
  one_pass.run_pass();
  const hydrodda::output::RunSummary expected = one_pass.summary();
  ASSERT_EQ(stopped.summary.blocks.size(), expected.blocks.size());
  for (std::size_t b = 0; b < expected.blocks.size(); ++b)
    EXPECT_EQ(stopped.summary.blocks[b].displacement, expected.blocks[b].displacement) << "block " << b;

  const run::ResumedRun resumed = run::open_resumed_run(parts.path);
  EXPECT_EQ(resumed.checkpoint.coupling.iterations, 1);
  const run::RunResult continued = run::resume(resumed, std::nullopt);
  EXPECT_EQ(continued.status, run::RunStatus::finished);
  EXPECT_EQ(continued.iterations, uninterrupted.iterations);
  expect_same_results(whole.path, parts.path);
}

// A resume whose model no longer fits its checkpoint (here a block fewer in the saved state,
// as a changed cut would give) fails before it runs a pass: it is refused, and the stopped
// run's summary.json is not replaced by a failure's with no result in it.
TEST(RunLayer, AResumeThatCannotTakeUpItsStateKeepsTheStoppedSummary) {
  const scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  Folder folder("resume-refused");
  const run::RunResult stopped = run::run(s, {folder.path, false, 1});
  ASSERT_EQ(stopped.status, run::RunStatus::stopped);
  const std::string summary = read_file(folder.path / "summary.json");
  run::ResumedRun resumed = run::open_resumed_run(folder.path);
  resumed.checkpoint.mechanics.blocks.pop_back();
  try {
    run::resume(resumed, std::nullopt);
    ADD_FAILURE() << "a state that does not fit the model was resumed";
  } catch (const run::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("could not be continued"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_file(folder.path / "summary.json"), summary);
}

// The checkpoint's input files: every file the scenario names, by key, absolute path and the
// hash of its content, which an edit of one byte changes; one that cannot be read is named.
TEST(RunLayer, TheInputFilesAreEveryFileTheScenarioNames) {
  Folder folder("input-files");
  fs::create_directories(folder.path);
  std::ofstream(folder.path / "traces.csv") << "0,0,1,1\n";
  std::ofstream(folder.path / "model.msh") << "$MeshFormat\n";
  scenario::Scenario s;
  s.geometry.emplace();
  s.geometry->fractures_file = folder.path / "traces.csv";
  s.mesh.emplace();
  s.mesh->file = folder.path / "model.msh";
  const std::vector<hydrodda::output::InputFile> files = run::hash_input_files(s);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].key, "geometry.fractures_file");
  EXPECT_EQ(files[0].path, (folder.path / "traces.csv").string());
  EXPECT_EQ(files[0].hash, hydrodda::output::hash_text("0,0,1,1\n"));
  EXPECT_EQ(files[1].key, "mesh.file");
  EXPECT_EQ(files[1].hash, hydrodda::output::hash_text("$MeshFormat\n"));
  std::ofstream(folder.path / "model.msh") << "$MeshFormaT\n";
  EXPECT_NE(run::hash_input_files(s)[1].hash, files[1].hash);
  fs::remove(folder.path / "traces.csv");
  EXPECT_THROW(run::hash_input_files(s), run::InputError);
}

TEST(RunLayer, AFailedPassLeavesTheRunAtTheLastFinishedPass) {
  // A failure during pass 2's DDA steps, after its flow solve (a stop request that throws
  // stands for a step that fails): the run fails, and its summary, blocks, heads and flows
  // alike, is pass 1's, as the model's after one pass; its flow section says so; the figures of
  // that pass are drawn, as every failed run's.
  scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_drained_fracture.toml");
  s.output.figures = {"png"};
  Folder folder("failed-pass");
  int reports = 0, asked_since = 0;
  run::Callbacks callbacks;
  callbacks.progress = [&](const run::ProgressReport&) { ++reports; };
  callbacks.stop_requested = [&] {
    // Asked before pass 2, before its first DDA step and before that step's first open–close
    // pass: the third is within its first step.
    if (reports == 1 && ++asked_since == 3) throw std::runtime_error("a DDA step failed");
    return false;
  };
  const run::RunResult failed = run::run(s, {folder.path}, callbacks);
  ASSERT_EQ(failed.status, run::RunStatus::failed) << failed.message;
  EXPECT_EQ(failed.iterations, 1);
  EXPECT_EQ(failed.message.rfind("coupling iteration 2 failed: DDA step 1 of 10 (t = 0.500000 s): a DDA step failed; "
                                 "summary.json and the figures hold "
                                 "coupling iteration 1, the last that finished",
                                 0),
            0u)
      << failed.message;
  EXPECT_TRUE(failed.good_state_kept);

  run::CoupledModel one_pass(s);
  one_pass.run_pass();
  const hydrodda::output::RunSummary expected = one_pass.summary();
  ASSERT_EQ(failed.summary.blocks.size(), expected.blocks.size());
  for (std::size_t b = 0; b < expected.blocks.size(); ++b)
    EXPECT_EQ(failed.summary.blocks[b].displacement, expected.blocks[b].displacement) << "block " << b;
  ASSERT_TRUE(failed.summary.flow);
  EXPECT_EQ(failed.summary.flow->iteration, 1);
  ASSERT_EQ(failed.summary.flow->boundaries.size(), expected.flow->boundaries.size());
  for (std::size_t i = 0; i < expected.flow->boundaries.size(); ++i)
    EXPECT_EQ(failed.summary.flow->boundaries[i].value, expected.flow->boundaries[i].value)
        << expected.flow->boundaries[i].name;
  EXPECT_EQ(read_file(folder.path / "summary.json"), hydrodda::output::format_summary(failed.summary));
  for (const char* figure : {"head.png", "permeability.png", "convergence.png"})
    EXPECT_TRUE(fs::exists(folder.path / "figures" / figure)) << figure;
}

TEST(RunLayer, AFailureInTheFirstPassLeavesNoFlowToReport) {
  // No pass finished: no flow section (the first pass's heads, of the blocks as built, are no
  // result), no iteration counted, no figure of a state that does not exist.
  scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_drained_fracture.toml");
  s.output.figures = {"png"};
  Folder folder("failed-first-pass");
  int asked = 0;
  run::Callbacks callbacks;
  callbacks.stop_requested = [&] {
    if (++asked == 3) throw std::runtime_error("a DDA step failed");
    return false;
  };
  const run::RunResult failed = run::run(s, {folder.path}, callbacks);
  ASSERT_EQ(failed.status, run::RunStatus::failed) << failed.message;
  EXPECT_EQ(failed.iterations, 0);
  EXPECT_FALSE(failed.summary.flow.has_value());
  EXPECT_NE(failed.message.find("no coupling iteration finished: there are no results"), std::string::npos)
      << failed.message;
  EXPECT_FALSE(fs::exists(folder.path / "figures" / "head.png"));
}

// in_situ_column.toml (mechanics alone, nine joints) to step `steps`, its fields every 10.
scenario::Scenario in_situ_column(int steps) {
  const fs::path file = kVerification / "in_situ_column.toml";
  const std::string text = scenario::apply_overrides(
      read_file(file), file, {{"mechanics.steps", std::to_string(steps)}, {"output.every", "10"}});
  return scenario::parse_scenario(text, file);
}

TEST(RunLayer, AFailedMechanicsRunDrawsItsLastOutputStepSayingHowItFailed) {
  // A step that fails at step 26 (a stop request that throws stands for it): the run fails,
  // and its apertures figure is drawn of step 20, the last output step, with a status line.
  // The same state drawn by a run that ends at step 20 has no status line: the pictures differ.
  Folder failed_folder("mechanics-failed"), finished_folder("mechanics-to-20");
  int steps = 0;
  run::Callbacks callbacks;
  callbacks.progress = [&](const run::ProgressReport&) { ++steps; };
  callbacks.stop_requested = [&] {  // asked before each step, first after 25 of them
    if (steps == 25) throw std::runtime_error("a DDA step failed: its matrix is singular");
    return false;
  };
  const run::RunResult failed = run::run(in_situ_column(100), {failed_folder.path}, callbacks);
  ASSERT_EQ(failed.status, run::RunStatus::failed) << failed.message;
  EXPECT_EQ(failed.message.rfind("mechanics failed at step 26 ", 0), 0u) << failed.message;
  const fs::path figure = failed_folder.path / "figures" / "apertures.png";
  ASSERT_TRUE(fs::exists(figure));

  const run::RunResult finished = run::run(in_situ_column(20), {finished_folder.path});
  ASSERT_EQ(finished.status, run::RunStatus::finished) << finished.message;
  EXPECT_NE(read_file(figure), read_file(finished_folder.path / "figures" / "apertures.png"));
  EXPECT_EQ(run::describe_status_for_figures("failed at step 26", "a DDA step failed: its matrix is singular"),
            "failed at step 26: a DDA step failed");
}

TEST(RunLayer, AnInterruptedMechanicsRunDrawsItsLastOutputStep) {
  Folder folder("mechanics-interrupted");
  Recorder recorder;
  recorder.stop_after_reports = 15;
  const run::RunResult stopped = run::run(in_situ_column(100), {folder.path}, recorder.callbacks());
  ASSERT_EQ(stopped.status, run::RunStatus::interrupted) << stopped.message;
  EXPECT_EQ(stopped.message, "interrupted at step 15 (t = 0.15 s)");
  EXPECT_TRUE(fs::exists(folder.path / "figures" / "apertures.png"));
}

TEST(RunLayer, AMechanicsRunInterruptedWithinAStepKeepsItsLastFinishedStep) {
  // Asked before each step and before each open–close pass within it: after 15 steps, the
  // second ask is within step 16, before its first pass. The run stops there with step 15's
  // summary and history, as the run stopped before step 16 has them.
  Folder within_folder("mechanics-interrupted-within"), between_folder("mechanics-interrupted-between");
  int steps = 0, asked_after = 0;
  run::Callbacks callbacks;
  callbacks.progress = [&](const run::ProgressReport&) { ++steps; };
  callbacks.stop_requested = [&] { return steps == 15 && ++asked_after == 2; };
  const run::RunResult within = run::run(in_situ_column(100), {within_folder.path}, callbacks);
  ASSERT_EQ(within.status, run::RunStatus::interrupted) << within.message;
  EXPECT_EQ(within.message.rfind("interrupted at step 15 (t = 0.15 s), interrupted within the step from t = 0.15 s", 0),
            0u)
      << within.message;

  Recorder recorder;
  recorder.stop_after_reports = 15;
  const run::RunResult between = run::run(in_situ_column(100), {between_folder.path}, recorder.callbacks());
  ASSERT_EQ(between.status, run::RunStatus::interrupted) << between.message;
  ASSERT_EQ(within.summary.blocks.size(), between.summary.blocks.size());
  for (std::size_t b = 0; b < between.summary.blocks.size(); ++b)
    EXPECT_EQ(within.summary.blocks[b].displacement, between.summary.blocks[b].displacement) << "block " << b;
  EXPECT_EQ(read_file(within_folder.path / "history.csv"), read_file(between_folder.path / "history.csv"));
}

TEST(RunLayer, AnInterruptedCoupledRunDrawsItsLastFinishedPass) {
  scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  s.output.figures = {"png"};
  Folder folder("coupled-interrupted");
  Recorder recorder;
  recorder.stop_after_reports = 1;
  const run::RunResult stopped = run::run(s, {folder.path}, recorder.callbacks());
  ASSERT_EQ(stopped.status, run::RunStatus::interrupted) << stopped.message;
  for (const char* figure : {"head.png", "permeability.png", "convergence.png", "apertures.png"})
    EXPECT_TRUE(fs::exists(folder.path / "figures" / figure)) << figure;
}

TEST(RunLayer, ACappedMatrixIsNamedInAWarning) {
  scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_drained_fracture.toml");
  s.flow->permeability_law = coupling::PermeabilityLaw::kozeny_carman;
  s.materials.front().matrix_porosity = 0.3;
  s.materials.front().grain_diameter = 0.018;  // Kozeny–Carman: 9.9e-8 m², a thousand times the cap
  const std::optional<std::string> warning = run::describe_capped_matrix(s);
  ASSERT_TRUE(warning.has_value());
  EXPECT_NE(warning->find("material." + s.materials.front().name + ": "), std::string::npos) << *warning;
  EXPECT_NE(warning->find("above flow.permeability_cap = 9.869e-11 m²"), std::string::npos) << *warning;
  s.flow->permeability_law = coupling::PermeabilityLaw::cubic;
  EXPECT_FALSE(run::describe_capped_matrix(s).has_value());
  EXPECT_GT(run::make_permeability_model(s).matrix_permeability(), 1e-8);
}

TEST(CoupledOutput, LargestOpeningIsTheFracturesOpening) {
  // history.csv's largest_opening is the widest opening of any fracture as fractures.csv
  // measures it that pass (its largest max_aperture), not a gap of a contact elsewhere: in this
  // seal every fracture stays closed, while an open contact pair among its blocks had a gap of
  // 0.019 m, which largest_opening was.
  const scenario::Scenario s =
      scenario::read_scenario(fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/seal_in_situ_stress.toml");
  Folder folder("largest-opening");
  const run::RunResult result = run::run(s, {folder.path});
  ASSERT_NE(result.status, run::RunStatus::failed) << result.message;
  const auto history = hydrodda::testing::read_csv(folder.path / "history.csv");
  const auto fractures = hydrodda::testing::read_csv(folder.path / "fractures.csv");
  const auto column = [](const std::vector<std::string>& header, const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t opening = column(history[0], "largest_opening"), step = column(fractures[0], "step"),
                    widest = column(fractures[0], "max_aperture");
  ASSERT_GE(history.size(), 2u);
  for (std::size_t row = 1; row < history.size(); ++row) {
    double largest = 0.0;
    for (std::size_t f = 1; f < fractures.size(); ++f)
      if (fractures[f][step] == history[row][0]) largest = std::max(largest, std::stod(fractures[f][widest]));
    EXPECT_EQ(std::stod(history[row][opening]), largest) << "iteration " << history[row][0];
  }
}

TEST(RunLayer, StopAfterIsForCoupledRunsOnlyAndLeavesNoFolder) {
  const scenario::Scenario s = scenario::read_scenario(kVerification / "flow_linear_head.toml");
  Folder folder("stop-after");
  EXPECT_THROW(run::run(s, {folder.path, false, 1}), run::InputError);
  EXPECT_FALSE(fs::exists(folder.path));
}

TEST(CoupledModel, PassesRunByHandEndWhereTheRunEnds) {
  // The model alone, stepped pass by pass with no file written, reaches the run's blocks and
  // flows bit for bit: the run folder is only a record of it.
  const scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  Folder folder("by-hand");
  const run::RunResult result = run::run(s, {folder.path});
  ASSERT_EQ(result.status, run::RunStatus::finished);

  run::CoupledModel model(s);
  bool converged = false;
  for (int pass = 0; pass < s.coupling.max_iterations && !converged; ++pass) converged = model.run_pass().converged;
  EXPECT_TRUE(converged);
  EXPECT_EQ(model.iterations(), result.iterations);
  const hydrodda::output::RunSummary by_hand = model.summary();
  ASSERT_EQ(by_hand.blocks.size(), result.summary.blocks.size());
  for (std::size_t b = 0; b < by_hand.blocks.size(); ++b) {
    EXPECT_EQ(by_hand.blocks[b].displacement, result.summary.blocks[b].displacement) << "block " << b;
    EXPECT_EQ(by_hand.blocks[b].stress, result.summary.blocks[b].stress) << "block " << b;
  }
  ASSERT_TRUE(by_hand.flow);
  EXPECT_EQ(by_hand.flow->balance, result.summary.flow->balance);
  expect_column_settled(by_hand);
}

TEST(CoupledModel, ANewFlowLoadCountsTheLoopsGrowthAfresh) {
  // A loading path (the breach command) starts each load from the state the last held. A state
  // that ended on a streak of growing changes (here 23 passes of it, set by hand) must not
  // make the new load's first pass, its step to that load, read as a diverging loop.
  const scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  run::CoupledModel model(s);
  for (int pass = 0; pass < 3; ++pass) model.run_pass();
  run::CoupledState held = model.export_state();
  held.coupling.growth = {23, 1e-12, 1e-11};
  std::vector<scenario::FlowBoundaryCondition> raised = s.flow->boundaries;
  raised[0].value = hydrodda::numerics::TimeTable(3.5);
  // A model built with the raised head, given the held state: the streak goes on.
  scenario::Scenario built_raised = s;
  built_raised.flow->boundaries = raised;
  run::CoupledModel carried_on(built_raised);
  carried_on.import_state(held);
  const hydrodda::coupling::PassReport carried = carried_on.run_pass();
  EXPECT_EQ(carried.growing_passes, 24);
  EXPECT_TRUE(carried.diverging);
  // The same load set on the model as a new load: the count starts afresh.
  model.import_state(held);
  model.set_flow_boundaries(raised);
  const hydrodda::coupling::PassReport fresh = model.run_pass();
  EXPECT_EQ(fresh.growing_passes, 0);
  EXPECT_FALSE(fresh.diverging);
}

TEST(CoupledModel, TheLoopRunWithAnObserverEndsWherePassesByHandEnd) {
  // CoupledModel::run (the staggered loop's bounded loop) tells its observer after every pass
  // and reaches, bit for bit, the state of the same passes run by hand; an observer that asks
  // to stop ends it before the next pass, the model at the last finished one.
  const scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  const auto encoded = [](const run::CoupledModel& model) {
    const run::CoupledState state = model.export_state();
    return hydrodda::output::encode_checkpoint({}, state.mechanics, state.coupling);
  };
  struct Observer final : hydrodda::coupling::PassObserver {
    std::vector<int> passes;
    int stop_before = 0;  // 0: never
    bool stop_requested() override { return stop_before > 0 && static_cast<int>(passes.size()) + 1 >= stop_before; }
    void after_pass(const hydrodda::coupling::PassReport& r) override { passes.push_back(r.iteration); }
  };
  run::CoupledModel by_hand(s), looped(s), stopped(s);
  bool converged = false;
  while (!converged && by_hand.iterations() < s.coupling.max_iterations) converged = by_hand.run_pass().converged;
  ASSERT_TRUE(converged);
  Observer all;
  const hydrodda::coupling::LoopResult result = looped.run({s.coupling.max_iterations, std::nullopt}, all);
  EXPECT_EQ(result.end, hydrodda::coupling::LoopEnd::converged);
  EXPECT_EQ(static_cast<int>(all.passes.size()), by_hand.iterations());
  EXPECT_EQ(all.passes.back(), by_hand.iterations());
  EXPECT_EQ(encoded(looped), encoded(by_hand));

  Observer stopping;
  stopping.stop_before = 2;
  EXPECT_EQ(stopped.run({s.coupling.max_iterations, std::nullopt}, stopping).end,
            hydrodda::coupling::LoopEnd::stop_requested);
  EXPECT_EQ(stopped.iterations(), 1);
  run::CoupledModel one_pass(s);
  one_pass.run_pass();
  EXPECT_EQ(encoded(stopped), encoded(one_pass));
}

TEST(CoupledModel, AnAbandonedPassLeavesTheModelAtTheLastFinishedPass) {
  // A stop request during pass 2's mechanics (after its flow solve, relaxation and forces) puts
  // every part of the state back as pass 1 left it, byte for byte as a checkpoint encodes it
  // (heads, Aitken's update and factor, the flow factor's permeability, the blocks); the model
  // then runs pass 2 again to the very state of a model never stopped.
  scenario::Scenario s = scenario::read_scenario(kVerification / "coupled_hydrostatic_column.toml");
  s.coupling.acceleration = coupling::Acceleration::aitken;
  const auto encoded = [](const run::CoupledModel& model) {
    const run::CoupledState state = model.export_state();
    return hydrodda::output::encode_checkpoint({}, state.mechanics, state.coupling);
  };
  run::CoupledModel never_stopped(s), stopped(s);
  never_stopped.run_pass();
  never_stopped.run_pass();
  stopped.run_pass();
  const std::string after_pass_one = encoded(stopped);
  int asked = 0;
  stopped.set_stop_request([&] { return ++asked > 3; });  // at DDA step 4 of pass 2
  EXPECT_THROW(stopped.run_pass(), hydrodda::coupling::PassInterrupted);
  EXPECT_EQ(asked, 4);
  EXPECT_EQ(stopped.iterations(), 1);
  EXPECT_EQ(encoded(stopped), after_pass_one);
  stopped.set_stop_request({});
  stopped.run_pass();
  EXPECT_EQ(encoded(stopped), encoded(never_stopped));
}

TEST(CoupledModel, TheFlowFactorsPrecisionGoesWithItsState) {
  // The seal over a reservoir, 150 m of head over its top, runs its third pass on the kept flow
  // factor without a correction, which rounds the factor to single precision. The exported
  // state says so, and a model that imports it holds its factor in single precision too (it is
  // corrected only where elements open, so the next pass's path depends on it:
  // FactorReuse.ARestoredSinglePrecisionFactorTakesTheSamePath).
  scenario::Scenario s =
      scenario::read_scenario(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/seal_over_reservoir.toml");
  ASSERT_EQ(s.flow->boundaries[0].name, "bottom");
  s.flow->boundaries[0].value = 175.0;
  s.coupling.ramp_passes = 1;  // the whole load at once: pass 3 is the second at the full load
  s.coupling.ramp_if_moved = 0;
  run::CoupledModel running(s);
  running.run_pass();
  EXPECT_FALSE(running.export_state().coupling.kept_factor_single_precision);  // factored afresh
  running.run_pass();
  running.run_pass();
  ASSERT_FALSE(running.loop().flow().factorised);
  ASSERT_EQ(running.loop().flow().corrected_elements, 0);
  const run::CoupledState state = running.export_state();
  EXPECT_TRUE(state.coupling.kept_factor_single_precision);
  run::CoupledModel resumed(s);
  resumed.import_state(state);
  EXPECT_TRUE(resumed.export_state().coupling.kept_factor_single_precision);
}

}  // namespace
