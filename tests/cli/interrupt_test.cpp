// Interrupts (SIGINT, SIGTERM) and kills at known points of a run: the program is held there
// (cli/hold_points.hpp) or signalled on an event the test sees, never after a delay.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "result_files.hpp"
#include "run_folder_compare.hpp"
#include "run_program.hpp"
#include "spawn_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::RunningProgram;
using hydrodda::testing::TemporaryFolder;
using hydrodda::testing::fresh_dir;

namespace {

nlohmann::json read_summary(const fs::path& folder) {
  return nlohmann::json::parse(std::ifstream(folder / "summary.json"));
}

}  // namespace

// SIGINT in the middle of a long coupling pass (held at its 50th DDA step's stop check, of a
// million): the program does not wait for the pass to end, it exits with 1 and leaves
// summary.json describing the last finished state.
TEST(Interrupt, ALongCouplingPassStopsAtTheNextStepAndReportsTheLastFinishedState) {
  const TemporaryFolder dir = fresh_dir("hydrodda-interrupt");
  const fs::path scenario = hydrodda::testing::edited_scenario(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper/six_block_lr_rl.toml",
      "hydrodda-long-pass-" + std::to_string(::getpid()), {{"steps = 100\n", "steps = 1000000\n"}});
  const fs::path out = dir.path / "run";
  RunningProgram program({"run", scenario.string(), "-o", out.string()}, dir.path.string() + ".log",
                         {"HYDRODDA_HOLD_AT_STOP_CHECK=50"});
  ASSERT_TRUE(program.wait_until_held()) << program.output();
  program.signal(SIGINT);
  // A million steps take many minutes: only an interrupt between steps ends the pass in time.
  ASSERT_TRUE(program.wait_for_exit(std::chrono::seconds(120))) << "the interrupt was not taken mid-pass";
  EXPECT_EQ(program.exit_code(), 1) << program.output();

  const auto summary = read_summary(out);
  EXPECT_EQ(summary["status"], "interrupted");
  EXPECT_EQ(summary["converged"], false);
  EXPECT_EQ(summary["iterations"], 0);
  const std::string message = summary["message"];
  EXPECT_NE(message.find("interrupted: coupling iteration 1 stopped at DDA step"), std::string::npos) << message;
  // No pass finished, so the blocks reported are the blocks as built: the steps taken before the
  // interrupt (which moved them under gravity and the fluid loads) are not reported as results.
  for (const auto& block : summary["blocks"]) {
    EXPECT_EQ(block["displacement"][0].get<double>(), 0.0) << "block " << block["id"];
    EXPECT_EQ(block["displacement"][1].get<double>(), 0.0) << "block " << block["id"];
  }
  fs::remove(scenario);
  fs::remove(dir.path.string() + ".log");
}

namespace {

// How a run interrupted somewhere ended: exit code 0 and converged (the interrupt came after its
// last stop check), or 1 with nothing left (while building its model) or a summary.json that
// does not say converged. The first folder with a checkpoint is resumed to its end.
void expect_a_clean_end(RunningProgram& program, const fs::path& out, bool& resumed_one) {
  ASSERT_TRUE(program.wait_for_exit()) << program.output();
  const int code = program.exit_code();
  if (code == 0) {
    EXPECT_EQ(read_summary(out)["converged"], true);
    return;
  }
  ASSERT_EQ(code, 1) << program.output();  // 128 + a signal when one killed it
  if (!fs::exists(out)) return;  // interrupted while building the model: nothing was written
  ASSERT_TRUE(fs::exists(out / "summary.json")) << program.output();
  EXPECT_EQ(read_summary(out)["converged"], false);
  if (fs::exists(out / "checkpoint.bin") && !resumed_one) {
    const auto resumed = hydrodda::testing::run_program("run -q --resume " + out.string());
    EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_EQ(read_summary(out)["converged"], true);
    resumed_one = true;
  }
}

// The number of lines in `text`.
std::size_t count_lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

// SIGTERM twice at every point of a small coupled run that logs a line (-v: the scenario read,
// meshed, the mechanics built, each pass; the run is held after its k-th line until the first
// comes, the second sent once it has gone on), and sent as each line appears without holding
// it, so that it lands wherever the run has got to (ordering the flow matrix with CHOLMOD,
// where METIS swaps signal handlers, among them): every run ends with exit code 0 or 1 and a
// folder it can be continued from, never killed, never a lost signal reported as success.
TEST(Interrupt, SigtermAtAnyMomentOfACoupledRunEndsItCleanly) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/coupled_hydrostatic_column.toml";
  const TemporaryFolder dir = fresh_dir("hydrodda-sigterm");
  const fs::path out = dir.path / "run", log = dir.path.string() + ".log";
  bool resumed_one = false;
  bool held = true;
  for (int line = 1; held && line < 200; ++line) {
    SCOPED_TRACE("SIGTERM after line " + std::to_string(line));
    {
      SCOPED_TRACE("held there");
      fs::remove_all(out);
      RunningProgram program({"run", "-v", scenario.string(), "-o", out.string()}, log,
                             {"HYDRODDA_HOLD_AFTER_LINE=", "HYDRODDA_HOLD_COUNT=" + std::to_string(line)});
      held = program.wait_until_held();
      if (held) {
        const std::size_t at_hold = program.output().size();
        program.signal(SIGTERM);
        // The second once the run has gone on past the hold (a line more, or its end).
        if (program.wait_for_output_change(at_hold)) program.signal(SIGTERM);
      }
      expect_a_clean_end(program, out, resumed_one);
      if (!held) EXPECT_EQ(program.exit_code(), 0) << "the run had fewer lines and was never signalled";
    }
    if (!held) break;
    {
      SCOPED_TRACE("sent as it appeared");
      fs::remove_all(out);
      RunningProgram program({"run", "-v", scenario.string(), "-o", out.string()}, log);
      if (program.wait_for([&](const std::string& output) { return count_lines(output) >= static_cast<std::size_t>(line); })) {
        program.signal(SIGTERM);
        program.signal(SIGTERM);
      }
      expect_a_clean_end(program, out, resumed_one);
    }
  }
  EXPECT_FALSE(held) << "the run never ended without being held";
  EXPECT_TRUE(resumed_one) << "no signal stopped the run with a checkpoint to resume";
  fs::remove(log);
}

// SIGTERM in a later mesh round of mesh.refine_tips (the asymmetric flexure with the cubic law:
// round 1 converges, round 2 runs on the mesh refined around its wedge tips): the run ends with
// exit code 1 and a folder that resumes on round 2's mesh, to the folder of a run never stopped,
// byte for byte (round_1/ too). A round 2 stopped before its first pass ends resumes from its
// start, which the round writes as a checkpoint once it has meshed. The run is held when round 1
// says it runs again on a refined mesh, until the signal comes.
TEST(Interrupt, ARunStoppedInALaterMeshRoundResumesOnThatRoundsMesh) {
  const std::string tag = std::to_string(::getpid());
  const fs::path file = hydrodda::testing::edited_scenario(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper/asymmetric_flexure_20mpa.toml", "hydrodda-rounds-" + tag,
      {{"permeability_law = \"kozeny-carman\"", "permeability_law = \"cubic\""},
       {"[mesh]\n", "[mesh]\nrefine_tips = true\n"},
       {"figures = [\"png\"]", "figures = []"}});
  const TemporaryFolder whole = fresh_dir("hydrodda-rounds-whole");
  const TemporaryFolder out = fresh_dir("hydrodda-rounds");
  const auto uninterrupted = hydrodda::testing::run_program("run -q " + file.string() + " -o " + whole.path.string());
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.output;
  ASSERT_TRUE(fs::exists(whole.path / "round_1"));

  RunningProgram program({"run", file.string(), "-o", out.path.string()}, out.path.string() + ".log",
                         {"HYDRODDA_HOLD_AFTER_LINE=running again on a mesh refined"});
  ASSERT_TRUE(program.wait_until_held()) << program.output();
  program.signal(SIGTERM);
  ASSERT_TRUE(program.wait_for_exit()) << program.output();
  ASSERT_EQ(program.exit_code(), 1) << program.output();
  ASSERT_TRUE(fs::exists(out.path / "round_1"));
  EXPECT_EQ(read_summary(out.path)["status"], "interrupted");
  ASSERT_TRUE(fs::exists(out.path / "checkpoint.bin"));
  const auto continued = hydrodda::testing::run_program("run -q --resume " + out.path.string());
  ASSERT_EQ(continued.exit_code, 0) << continued.output;
  hydrodda::testing::expect_same_results(whole.path, out.path);
  hydrodda::testing::expect_same_results(whole.path / "round_1", out.path / "round_1");
  fs::remove(file);
  fs::remove(out.path.string() + ".log");
}

namespace {

// Whether `pid` has SIGTERM in its blocked set (/proc/PID/status, SigBlk: a hex mask, bit
// SIGTERM − 1).
bool blocks_sigterm(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("SigBlk:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (SIGTERM - 1)) & 1u;
  return false;
}

}  // namespace

// An interrupt in the first moments of the program, for every command: main blocks SIGINT and
// SIGTERM first thing, so from then on one waits for the signal thread instead of ending the
// process by the default action. `check` had no signal thread at all and died of the signal.
// The signal is sent as soon as the blocked set shows SIGTERM (main's first act), and with the
// program held after each of its first lines.
TEST(Interrupt, AnInterruptRightAfterStartIsAMessageNotASignal) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/examples/jointed_seal.toml";
  const TemporaryFolder dir = fresh_dir("hydrodda-early");
  const fs::path out = dir.path / "run", log = dir.path.string() + ".log";
  for (const std::string command : {"check", "run"}) {
    const std::vector<std::string> arguments =
        command == "check" ? std::vector<std::string>{"check", scenario.string()}
                           : std::vector<std::string>{"run", scenario.string(), "-o", out.string()};
    for (int line = 0; line <= 3; ++line) {
      SCOPED_TRACE(command + (line == 0 ? ", SIGTERM once main began" : ", held after line " + std::to_string(line)));
      fs::remove_all(out);
      std::vector<std::string> hold;
      if (line > 0) hold = {"HYDRODDA_HOLD_AFTER_LINE=", "HYDRODDA_HOLD_COUNT=" + std::to_string(line)};
      RunningProgram program(arguments, log, hold);
      if (line == 0) {
        // Before main (the dynamic loader mapping the libraries) nothing of ours can take a
        // signal; main's first act shows in the blocked set.
        ASSERT_TRUE(program.wait_for([&](const std::string&) { return blocks_sigterm(program.pid()); }))
            << "the program never blocked SIGTERM";
      } else {
        ASSERT_TRUE(program.wait_until_held()) << program.output();
      }
      program.signal(SIGTERM);
      ASSERT_TRUE(program.wait_for_exit()) << program.output();
      // 1 interrupted; 0 only when it ended before a signal it was not held for (check on an
      // idle machine).
      if (line == 0) EXPECT_TRUE(program.exit_code() == 1 || program.exit_code() == 0) << program.exit_code();
      else EXPECT_EQ(program.exit_code(), 1) << program.output();
    }
  }
  fs::remove(log);
}

namespace {

// `hydrodda run SCENARIO` killed (SIGKILL) when it begins to draw its figures (held there): the
// folder's summary.json then, or null when there is none.
nlohmann::json kill_while_drawing_figures(const fs::path& scenario, const std::string& name) {
  const TemporaryFolder out = fresh_dir("hydrodda-killed-figures-" + name);
  RunningProgram program({"run", scenario.string(), "-o", out.path.string()}, out.path.string() + ".log",
                         {"HYDRODDA_HOLD_AFTER_LINE=figures: drawing in"});
  const bool held = program.wait_until_held();
  EXPECT_TRUE(held) << "the run never began to draw its figures: " << program.output();
  program.signal(SIGKILL);
  program.wait_for_exit();
  fs::remove(out.path.string() + ".log");
  if (!held || !fs::exists(out.path / "summary.json")) return nullptr;
  return read_summary(out.path);
}

}  // namespace

// Item 17: SIGKILL while the figures are drawn after convergence left the fields and a
// converged checkpoint but no summary.json, and --resume refused ("already converged"): the
// summary is written first, so whenever figures/ exists, so does summary.json. Likewise for a
// flow-only run (head, permeability) and a mechanics-only one (apertures), which wrote it last.
TEST(Interrupt, ARunKilledWhileDrawingItsFiguresHasItsSummary) {
  const nlohmann::json summary =
      kill_while_drawing_figures(fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/paper/six_block_lr_rl.toml", "coupled");
  ASSERT_FALSE(summary.is_null()) << "no summary.json";
  EXPECT_EQ(summary["converged"], true);
}

TEST(Interrupt, AFlowRunKilledWhileDrawingItsFiguresHasItsSummary) {
  const nlohmann::json summary = kill_while_drawing_figures(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/flow_three_fractures.toml", "flow");
  ASSERT_FALSE(summary.is_null()) << "no summary.json";
  EXPECT_EQ(summary["converged"], true);
  EXPECT_FALSE(summary["flow"].is_null());
}

TEST(Interrupt, AMechanicsRunKilledWhileDrawingItsFiguresHasItsSummary) {
  const nlohmann::json summary = kill_while_drawing_figures(
      fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/roller_oedometer.toml", "mechanics");
  ASSERT_FALSE(summary.is_null()) << "no summary.json";
  EXPECT_EQ(summary["converged"], true);
  EXPECT_EQ(summary["blocks"].size(), 10u);
}

namespace {

// Whether `pid` has mapped the file named `library` (/proc/PID/maps).
bool has_loaded(pid_t pid, const std::string& library) {
  std::ifstream maps("/proc/" + std::to_string(pid) + "/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find(library) != std::string::npos) return true;
  return false;
}

}  // namespace

// Item 4: an interrupt while Gmsh meshes ends the run at once (Gmsh cannot be stopped between
// steps; nothing exists yet to keep). A unit square of some 160,000 triangles takes 5-20 s to
// mesh on this machine; SIGTERM as soon as the mesher plugin is loaded (it is loaded when
// meshing begins) finds Gmsh at work, and the run ends without the mesh it was making.
TEST(Interrupt, AnInterruptWhileMeshingEndsTheRunAtOnce) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "tests/cli/scenarios/fine_square_mesh.toml";
  const TemporaryFolder out = fresh_dir("hydrodda-meshing");
  RunningProgram program({"run", scenario.string(), "-o", out.path.string()}, out.path.string() + ".log");
  ASSERT_TRUE(program.wait_for([&](const std::string&) { return has_loaded(program.pid(), "hydrodda_gmsh_mesher.so"); }))
      << "the mesher was never loaded: " << program.output();
  program.signal(SIGTERM);
  ASSERT_TRUE(program.wait_for_exit()) << program.output();
  EXPECT_EQ(program.exit_code(), 1) << program.output();
  const std::string output = program.output();
  EXPECT_NE(output.find("interrupted before any result was written"), std::string::npos) << output;
  EXPECT_EQ(output.find(" nodes, "), std::string::npos) << "the run waited for the mesh: " << output;
  EXPECT_FALSE(fs::exists(out.path)) << "the run folder it made, empty, is removed";
  fs::remove(out.path.string() + ".log");
}

// A flow-only run honours an interrupt after its solve (which, with the fields, the summary and
// the figures, takes as long again as the meshing on a large mesh): held when it reports the
// solve, it stops with exit code 1 and says so, in its last line and in summary.json, which has
// no result of a solve it never summarised. It went on to write everything and exited with 0.
TEST(Interrupt, AFlowRunInterruptedAfterItsSolveSaysSo) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/flow_three_fractures.toml";
  const TemporaryFolder out = fresh_dir("hydrodda-flow-interrupted");
  RunningProgram program({"run", scenario.string(), "-o", out.path.string()}, out.path.string() + ".log",
                         {"HYDRODDA_HOLD_AFTER_LINE=flow solved"});
  ASSERT_TRUE(program.wait_until_held()) << program.output();
  program.signal(SIGTERM);
  ASSERT_TRUE(program.wait_for_exit()) << program.output();
  EXPECT_EQ(program.exit_code(), 1) << program.output();
  EXPECT_NE(program.output().find("error: interrupted after the flow solve"), std::string::npos) << program.output();
  const auto summary = read_summary(out.path);
  EXPECT_EQ(summary["status"], "interrupted");
  EXPECT_EQ(summary["converged"], false);
  EXPECT_TRUE(!summary.contains("flow") || summary["flow"].is_null()) << summary["flow"];
  EXPECT_FALSE(fs::exists(out.path / "figures"));
  fs::remove(out.path.string() + ".log");
}

// ... and between its figures: held as it begins to draw them, it draws none and says so; its
// results, written by then, are kept.
TEST(Interrupt, AFlowRunInterruptedWhileDrawingItsFiguresSaysSo) {
  const fs::path scenario = fs::path(HYDRODDA_SOURCE_DIR) / "scenarios/verification/flow_three_fractures.toml";
  const TemporaryFolder out = fresh_dir("hydrodda-flow-figures-interrupted");
  RunningProgram program({"run", scenario.string(), "-o", out.path.string()}, out.path.string() + ".log",
                         {"HYDRODDA_HOLD_AFTER_LINE=figures: drawing in"});
  ASSERT_TRUE(program.wait_until_held()) << program.output();
  program.signal(SIGINT);
  ASSERT_TRUE(program.wait_for_exit()) << program.output();
  EXPECT_EQ(program.exit_code(), 1) << program.output();
  EXPECT_NE(program.output().find("error: interrupted after the results were written, before all figures were drawn"),
            std::string::npos)
      << program.output();
  const auto summary = read_summary(out.path);
  EXPECT_EQ(summary["status"], "interrupted");
  EXPECT_TRUE(summary.contains("flow") && !summary["flow"].is_null());
  EXPECT_TRUE(fs::is_empty(out.path / "figures"));
  fs::remove(out.path.string() + ".log");
}
