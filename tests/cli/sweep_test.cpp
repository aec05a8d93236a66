// `hydrodda sweep` through the real program: every case run and gathered, a failed case
// reported and never hidden, bad keys refused before anything runs, and an interrupt passed on.

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>

#include "run_program.hpp"
#include "spawn_program.hpp"

namespace fs = std::filesystem;
using hydrodda::testing::read_csv;
using hydrodda::testing::run_program;

namespace {

const fs::path kSource = HYDRODDA_SOURCE_DIR;


fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(Sweep, RunsEveryCombinationAndGathersTheSummaries) {
  const fs::path out = fresh_dir("hydrodda-sweep-flow");
  const auto result = run_program("sweep " + (kSource / "scenarios/verification/flow_linear_head.toml").string() +
                                   " --set flow.boundary[0].head=3,5 --set flow.region[0].permeability=1e-12,2e-12"
                                   " --jobs 2 -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output.find("warning(s) in"), std::string::npos) << result.output;
  const auto rows = read_csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"case", "flow.boundary[0].head", "flow.region[0].permeability",
                                               "status", "converged", "iterations",
                                               "flow.regions.rock.effective_conductivity", "message"}));
  const std::vector<std::array<std::string, 3>> expected{
      {"case_000", "3", "1e-12"}, {"case_001", "3", "2e-12"}, {"case_002", "5", "1e-12"}, {"case_003", "5", "2e-12"}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& row = rows[i + 1];
    ASSERT_EQ(row.size(), 8u);
    EXPECT_EQ(row[0], expected[i][0]);
    EXPECT_EQ(row[1], expected[i][1]);
    EXPECT_EQ(row[2], expected[i][2]);
    EXPECT_EQ(row[3], "ok");
    EXPECT_EQ(row[4], "true");
    // Uniform permeability k: K_eff = k ρ g / μ exactly (1000 kg/m3, 9.81 m/s2, 1e-3 Pa s),
    // whatever the head drop, as Darcy's law is linear. Round-off only: 1e-9 relative.
    const double k = std::stod(row[2]);
    EXPECT_NEAR(std::stod(row[6]), k * 1000.0 * 9.81 / 1e-3, 1e-9 * k * 1e7) << row[0];
    EXPECT_EQ(row[7], "");
  }
  // Each case ran from its own scenario file, with the value set.
  std::ifstream case_file(out / "case_002/scenario.toml");
  std::stringstream text;
  text << case_file.rdbuf();
  EXPECT_NE(text.str().find("head = 5.0"), std::string::npos) << text.str();
  EXPECT_TRUE(fs::exists(out / "case_003/summary.json"));
  std::ifstream png(out / "sweep.png", std::ios::binary);
  std::string signature(8, '\0');
  png.read(signature.data(), 8);
  EXPECT_EQ(signature, std::string("\x89PNG\r\n\x1a\n", 8));
  // A second sweep into the same folder is refused unless asked to overwrite.
  EXPECT_EQ(run_program("sweep " + (kSource / "scenarios/verification/flow_linear_head.toml").string() +
                        " --set flow.boundary[0].head=3 -o " + out.string())
                .exit_code,
            2);
  fs::remove_all(out);
}

// A case whose run warned says so in the sweep's line for it: the symmetric flexure with the
// cubic law on 2 cm fracture elements, whose central joint's wedge tips draw flow from the
// matrix over about 2 mm (docs/coupling.md, "Wedge tips"), converges, and its run.log warns.
TEST(Sweep, ACaseThatWarnedSaysSo) {
  const fs::path out = fresh_dir("hydrodda-sweep-warned");
  const auto result = run_program("sweep " + (kSource / "scenarios/paper/symmetric_flexure_20m.toml").string() +
                                   " --set flow.permeability_law=cubic --set mesh.fracture_size=0.02 -o " +
                                   out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("case_000 (flow.permeability_law=cubic, mesh.fracture_size=0.02): ok ("),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("warning(s) in case_000/run.log)"), std::string::npos) << result.output;
  fs::remove_all(out);
}

TEST(Sweep, AFailedCaseIsReportedAndTheOthersFinish) {
  const fs::path out = fresh_dir("hydrodda-sweep-failed");
  // A density of 1e308 makes the mass overflow: the stiffness matrix is not finite, and that
  // run fails in its first step, after the reader and the model checks have passed.
  const auto result = run_program("sweep " + (kSource / "scenarios/verification/free_fall.toml").string() +
                                  " --set mechanics.end_time=0.05 --set material.rock.density=2500,1e308"
                                  " --column measure.centre.displacement.1 -o " + out.string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("1 of 2 case(s) gave no converged result (1 failed)"), std::string::npos)
      << result.output;
  const auto rows = read_csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"case", "mechanics.end_time", "material.rock.density", "status",
                                               "converged", "iterations", "measure.centre.displacement.1",
                                               "message"}));
  // Free fall for 0.05 s: u_y = −g t²/2 = −0.0122625 m; the explicit step is exact for
  // constant acceleration up to round-off (1e-9).
  ASSERT_EQ(rows[1].size(), 8u);
  EXPECT_EQ(rows[1][3], "ok");
  EXPECT_NEAR(std::stod(rows[1][6]), -0.5 * 9.81 * 0.05 * 0.05, 1e-9);
  ASSERT_EQ(rows[2].size(), 8u);
  EXPECT_EQ(rows[2][0], "case_001");
  EXPECT_EQ(rows[2][3], "failed");
  EXPECT_EQ(rows[2][4], "false");
  EXPECT_EQ(rows[2][6], "");  // no value: its summary's is the initial state's, no result
  EXPECT_NE(rows[2][7].find("mechanics failed at step 1"), std::string::npos) << rows[2][7];
  EXPECT_NE(rows[2][7].find("not finite"), std::string::npos) << rows[2][7];
  fs::remove_all(out);
}

// A case that stops at coupling.max_iterations without meeting the tolerance is "not converged",
// never "ok": the sweep says how many, exits with 1, and still gathers the other case.
TEST(Sweep, AnUnconvergedCaseIsMarkedAndCounted) {
  const fs::path out = fresh_dir("hydrodda-sweep-unconverged");
  const auto result = run_program("sweep " + (kSource / "scenarios/verification/coupled_hydrostatic_column.toml").string() +
                                  " --set flow.boundary[0].head=3,3.5 --set coupling.max_iterations=1,20 --zip"
                                  " --column measure.top.displacement.1 -o " + out.string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("1 of 2 case(s) gave no converged result (1 not converged)"), std::string::npos)
      << result.output;
  const auto rows = read_csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(rows[1].size(), 8u);
  EXPECT_EQ(rows[1][3], "not converged");
  EXPECT_EQ(rows[1][4], "false");
  EXPECT_EQ(rows[1][5], "1");
  EXPECT_NE(rows[1][7].find("did not converge in 1 iteration"), std::string::npos) << rows[1][7];
  ASSERT_EQ(rows[2].size(), 8u);
  EXPECT_EQ(rows[2][3], "ok");
  EXPECT_EQ(rows[2][4], "true");
  EXPECT_TRUE(fs::exists(out / "sweep.png"));
  // Each case's title (its figures' and summary's) names its values.
  std::ifstream summary(out / "case_001/summary.json");
  std::stringstream text;
  text << summary.rdbuf();
  EXPECT_NE(text.str().find("block column in still water — head at bottom = 3.5 m, coupling iterations allowed = 20"),
            std::string::npos)
      << text.str();
  fs::remove_all(out);
}

TEST(Sweep, BadInputIsRefusedBeforeAnythingRuns) {
  const fs::path out = fresh_dir("hydrodda-sweep-bad");
  const std::string scenario = (kSource / "scenarios/verification/flow_linear_head.toml").string();
  const auto no_table = run_program("sweep " + scenario + " --set nosuch.value=1 -o " + out.string());
  EXPECT_EQ(no_table.exit_code, 2);
  EXPECT_NE(no_table.output.find("nosuch.value: the scenario has no 'nosuch'"), std::string::npos)
      << no_table.output;
  const auto index = run_program("sweep " + scenario + " --set flow.boundary[5].head=1 -o " + out.string());
  EXPECT_EQ(index.exit_code, 2);
  EXPECT_NE(index.output.find("index 5 is out of range"), std::string::npos) << index.output;
  // The second value is out of range for the reader: no case runs, not even the first.
  const auto value = run_program("sweep " + scenario + " --set flow.fluid.viscosity=1e-3,-1 -o " + out.string());
  EXPECT_EQ(value.exit_code, 2);
  EXPECT_NE(value.output.find("case_001 (flow.fluid.viscosity=-1)"), std::string::npos) << value.output;
  EXPECT_NE(value.output.find("flow.fluid.viscosity: must be > 0"), std::string::npos) << value.output;
  // A value only building the model refuses (a measure point in no block), as `check` does.
  const auto model = run_program("sweep " + (kSource / "scenarios/verification/free_fall.toml").string() +
                                 " --set mechanics.measure[0].point=[0.5,0.5],[50,50] -o " + out.string());
  EXPECT_EQ(model.exit_code, 2);
  EXPECT_NE(model.output.find("(50, 50) lies in no block"), std::string::npos) << model.output;
  const auto malformed = run_program("sweep " + scenario + " --set flow.boundary -o " + out.string());
  EXPECT_EQ(malformed.exit_code, 2);
  EXPECT_NE(malformed.output.find("expected KEY=V1,V2"), std::string::npos) << malformed.output;
  EXPECT_FALSE(fs::exists(out));
}

// Item 18: a case's errors cited case_001/scenario.toml:LINE, the rewritten file of a case that
// is never written (the sweep does not start). A value a --set made is cited by the --set; any
// other by the line of the same key in the scenario file.
TEST(Sweep, ErrorsCiteTheSetAndTheScenarioFileNotTheCasesFile) {
  const fs::path out = fresh_dir("hydrodda-sweep-cite");
  const fs::path flow = kSource / "scenarios/verification/flow_linear_head.toml";
  const auto value = run_program("sweep " + flow.string() + " --set flow.fluid.viscosity=1e-3,-1 -o " + out.string());
  EXPECT_EQ(value.exit_code, 2);
  EXPECT_NE(value.output.find("error: --set flow.fluid.viscosity=-1: flow.fluid.viscosity: must be > 0"),
            std::string::npos)
      << value.output;
  EXPECT_EQ(value.output.find("scenario.toml"), std::string::npos) << value.output;

  // time_step = 1e-12 makes end_time = 1 s too many steps: the error is end_time's, at its line.
  const fs::path fall = kSource / "scenarios/verification/free_fall.toml";
  std::ifstream in(fall);
  int end_time_line = 0;
  std::string line;
  for (int n = 1; std::getline(in, line) && end_time_line == 0; ++n)
    if (line.rfind("end_time", 0) == 0) end_time_line = n;
  ASSERT_GT(end_time_line, 0);
  const auto steps = run_program("sweep " + fall.string() + " --set mechanics.time_step=1e-3,1e-12 -o " + out.string());
  EXPECT_EQ(steps.exit_code, 2);
  EXPECT_NE(steps.output.find("case_001 (mechanics.time_step=1e-12)"), std::string::npos) << steps.output;
  EXPECT_NE(steps.output.find(fall.string() + ":" + std::to_string(end_time_line) + ": mechanics.end_time: "),
            std::string::npos)
      << steps.output;
  EXPECT_EQ(steps.output.find("scenario.toml"), std::string::npos) << steps.output;
  EXPECT_FALSE(fs::exists(out));
}

// --zip takes the lists together: two cases, not four, each key at the same position; lists of
// different lengths are refused before anything runs.
TEST(Sweep, ZipTakesTheListsTogether) {
  const fs::path out = fresh_dir("hydrodda-sweep-zip");
  const std::string scenario = (kSource / "scenarios/verification/flow_linear_head.toml").string();
  const auto result = run_program("sweep " + scenario +
                                  " --set flow.boundary[0].head=3,5 --set flow.region[0].permeability=1e-12,2e-12"
                                  " --zip --title 'Two zipped keys' -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto rows = read_csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][1], "3");
  EXPECT_EQ(rows[1][2], "1e-12");
  EXPECT_EQ(rows[2][1], "5");
  EXPECT_EQ(rows[2][2], "2e-12");
  EXPECT_TRUE(fs::exists(out / "sweep.png"));
  fs::remove_all(out);

  const auto uneven = run_program("sweep " + scenario +
                                  " --set flow.boundary[0].head=3,5,7 --set flow.region[0].permeability=1e-12,2e-12"
                                  " --zip -o " + out.string());
  EXPECT_EQ(uneven.exit_code, 2);
  EXPECT_NE(uneven.output.find("zipped keys need as many values each"), std::string::npos) << uneven.output;
  EXPECT_FALSE(fs::exists(out));
}

// The same key twice ran with its last value and gave sweep.csv the column twice.
TEST(Sweep, AKeyGivenTwiceIsRefused) {
  const fs::path out = fresh_dir("hydrodda-sweep-twice");
  const std::string scenario = (kSource / "scenarios/verification/flow_linear_head.toml").string();
  for (const char* zip : {"", " --zip"}) {
    const auto result = run_program("sweep " + scenario + " --set flow.boundary[0].head=3,5 --set flow.boundary[0].head=7,9" +
                                    zip + " -o " + out.string());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--set flow.boundary[0].head: the key is given twice"), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(out));
  }
}

// A sweep of `scenario` (in the source tree) with `arguments` (--set ..., -o ...), started in its
// own process group (so that a signal reaches the sweep only, which must pass it on to its
// cases), its output in LOG, with `environment` (a hold point, cli/hold_points.hpp, for it or its
// cases, which inherit it).
std::unique_ptr<hydrodda::testing::RunningProgram> start_sweep(const std::string& scenario,
                                                               const std::vector<std::string>& arguments,
                                                               const fs::path& log,
                                                               const std::vector<std::string>& environment) {
  std::vector<std::string> all{"sweep", (kSource / scenario).string()};
  all.insert(all.end(), arguments.begin(), arguments.end());
  return std::make_unique<hydrodda::testing::RunningProgram>(all, log, environment, true);
}

// A sweep of the six-block model over `heads`, `jobs` at a time, whose cases hold where
// `hold` says; SIGINT to the sweep once `ready()`, and sweep.csv's rows after the sweep exited
// with 1.
std::vector<std::vector<std::string>> interrupt_sweep(const fs::path& out, const std::string& heads, const std::string& jobs,
                                                      const std::vector<std::string>& hold,
                                                      const std::function<bool()>& ready) {
  const auto sweep = start_sweep("scenarios/paper/six_block_lr_rl.toml",
                                 {"--set", "flow.boundary[0].head=" + heads, "--jobs", jobs, "-o", out.string()},
                                 out.string() + ".log", hold);
  EXPECT_TRUE(sweep->wait_for([&](const std::string&) { return ready(); })) << sweep->output();
  sweep->signal(SIGINT);
  EXPECT_TRUE(sweep->wait_for_exit()) << sweep->output();
  EXPECT_EQ(sweep->exit_code(), 1) << sweep->output();
  fs::remove(out.string() + ".log");
  return read_csv(out / "sweep.csv");
}

// A case interrupted as it starts (the sweep passes the interrupt on at once) says it was
// interrupted: it starts with SIGINT and SIGTERM blocked, so a signal that comes while its
// program still loads waits for its signal thread instead of killing it with an empty run.log
// ("exit code 130"). The interrupt is sent as soon as the second case's log appears (opened as
// it is started, before its program has loaded); the cases hold at their first stop check, so
// that neither can end before it comes.
TEST(Sweep, ACaseInterruptedAtStartUpSaysInterrupted) {
  const fs::path out = fresh_dir("hydrodda-sweep-startup");
  const auto rows = interrupt_sweep(out, "5,10", "2", {"HYDRODDA_HOLD_AT_STOP_CHECK=1"},
                                    [&] { return fs::exists(out / "case_001/run.log"); });
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(rows[0][2], "status");  // case, the head, status, ...
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r][2], "interrupted");
    EXPECT_NE(rows[r].back().find("interrupted"), std::string::npos) << rows[r].back();
    EXPECT_EQ(rows[r].back().find("exit code 13"), std::string::npos) << rows[r].back();
  }
  fs::remove_all(out);
}

// The first case is held after its first coupling iteration until the interrupt comes: it
// stops there, and no further case starts.
TEST(Sweep, InterruptStopsLaunchingAndReachesTheRunningCase) {
  const fs::path out = fresh_dir("hydrodda-sweep-interrupt");
  const auto rows = interrupt_sweep(out, "5,10,15", "1", {"HYDRODDA_HOLD_AFTER_LINE=iteration 1: head change"}, [&] {
    return hydrodda::testing::read_whole_file(out / "case_000/run.log").find("held: ") != std::string::npos;
  });
  ASSERT_EQ(rows.size(), 4u);
  ASSERT_EQ(rows[0][2], "status");
  EXPECT_EQ(rows[1][2], "interrupted");  // the running case stopped at the interrupt ...
  EXPECT_NE(rows[1].back().find("interrupted after coupling iteration 1"), std::string::npos) << rows[1].back();
  EXPECT_EQ(rows[2][2], "not run");  // ... and no further case started
  EXPECT_EQ(rows[3][2], "not run");
  EXPECT_FALSE(fs::exists(out / "case_001/summary.json"));
  fs::remove_all(out);
}

// A case interrupted while it builds its model (held as it is about to mesh) ends at once with
// exit code 1 and writes nothing; the sweep passed the interrupt on, so the case is listed as
// interrupted, not failed.
TEST(Sweep, ACaseInterruptedWhileBuildingItsModelIsListedAsInterrupted) {
  const fs::path out = fresh_dir("hydrodda-sweep-meshing");
  const auto sweep = start_sweep("tests/cli/scenarios/fine_square_mesh.toml",
                                 {"--set", "flow.boundary[0].head=1,2", "--jobs", "1", "-o", out.string()},
                                 out.string() + ".log", {"HYDRODDA_HOLD_AFTER_LINE=expected"});
  ASSERT_TRUE(hydrodda::testing::wait_for_text(out / "case_000/run.log", "held: ", [&] { return sweep->running(); }))
      << sweep->output();
  sweep->signal(SIGINT);
  ASSERT_TRUE(sweep->wait_for_exit()) << sweep->output();
  EXPECT_EQ(sweep->exit_code(), 1) << sweep->output();
  const auto rows = read_csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(rows[0][2], "status");
  EXPECT_EQ(rows[1][2], "interrupted");
  EXPECT_NE(rows[1].back().find("interrupted before any result was written"), std::string::npos) << rows[1].back();
  EXPECT_EQ(rows[2][2], "not run");
  EXPECT_NE(sweep->output().find("1 interrupted, 1 not run"), std::string::npos) << sweep->output();
  fs::remove(out.string() + ".log");
  fs::remove_all(out);
}

// More cases than one sweep runs are refused before any is built (10^9 ended in bad_alloc),
// naming the keys whose values multiply to the count: none of the values is even read (the
// viscosities here are all invalid, and no case's error is printed).
TEST(Sweep, TooManyCasesAreRefusedBeforeAnyIsBuilt) {
  const fs::path out = fresh_dir("hydrodda-sweep-too-many");
  std::string heads, viscosities;
  for (int i = 1; i <= 101; ++i) heads += (i > 1 ? "," : "") + std::to_string(i);
  for (int i = 1; i <= 100; ++i) viscosities += (i > 1 ? ",-" : "-") + std::to_string(i);
  const auto result = run_program("sweep " + (kSource / "scenarios/verification/flow_linear_head.toml").string() +
                                  " --set flow.boundary[0].head=" + heads + " --set flow.fluid.viscosity=" +
                                  viscosities + " -o " + out.string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("the sweep has 10100 cases (--set flow.boundary[0].head: 101 value(s) × --set "
                               "flow.fluid.viscosity: 100 value(s)); at most 10000"),
            std::string::npos)
      << result.output.substr(0, 2000);
  EXPECT_EQ(result.output.find("case_000"), std::string::npos) << result.output.substr(0, 2000);
  EXPECT_FALSE(fs::exists(out));
}

// An interrupt while the sweep checks its cases (40,000 took a minute, and the interrupt waited
// for all of them) stops it there: exit code 1, saying so, and nothing written. The sweep is
// held once it has checked its third case.
TEST(Sweep, AnInterruptWhileCheckingTheCasesStopsTheSweepThere) {
  const fs::path out = fresh_dir("hydrodda-sweep-preparing");
  const auto sweep = start_sweep("scenarios/verification/flow_linear_head.toml",
                                 {"--set", "flow.boundary[0].head=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20",
                                  "--set", "flow.region[0].permeability=1e-12,2e-12,3e-12,4e-12,5e-12,6e-12,7e-12,8e-12,"
                                           "9e-12,1e-11",
                                  "-o", out.string()},
                                 out.string() + ".log", {"HYDRODDA_HOLD_AFTER_LINE=case_002 ("});
  ASSERT_TRUE(sweep->wait_until_held()) << sweep->output();
  sweep->signal(SIGTERM);
  ASSERT_TRUE(sweep->wait_for_exit()) << sweep->output();
  EXPECT_EQ(sweep->exit_code(), 1) << sweep->output();
  EXPECT_NE(sweep->output().find("error: interrupted while checking the cases (3 of 200 checked); nothing was run or "
                                 "written"),
            std::string::npos)
      << sweep->output();
  EXPECT_FALSE(fs::exists(out));
  fs::remove(out.string() + ".log");
}

}  // namespace
