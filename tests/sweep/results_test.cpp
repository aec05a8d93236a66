// SweepResults on case folders written by hand: each way a case can end gets its own status in
// sweep.csv and the summary line, only converged cases are drawn on the line, and a case that
// failed or was interrupted has no value.

#include "sweep/results.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
namespace sweep = hydrodda::sweep;

namespace {

struct Folder {
  fs::path path;
  Folder() : path(fs::temp_directory_path() / ("hydrodda-sweep-results-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
};

// A case folder holding `summary` as its summary.json (none when empty) and `log` as run.log.
fs::path write_case(const fs::path& root, const std::string& name, const std::string& summary,
                    const std::string& log = "") {
  const fs::path dir = root / name;
  fs::create_directories(dir);
  fs::remove(dir / "summary.json");
  if (!summary.empty()) std::ofstream(dir / "summary.json") << summary;
  std::ofstream(dir / "run.log") << log;
  return dir;
}

std::string summary(const std::string& status, bool converged, int iterations, double value,
                    const std::string& message = "") {
  return "{\"status\": \"" + status + "\", \"message\": \"" + message + "\", \"converged\": " +
         (converged ? "true" : "false") + ", \"iterations\": " + std::to_string(iterations) +
         ", \"flow\": {\"regions\": {\"seal\": {\"normalised_conductivity\": " + std::to_string(value) + "}}}}";
}

// Six cases of one swept head, each ending a different way.
class SweepResultsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::vector<std::vector<hydrodda::scenario::Override>> cases;
    for (const std::string& v : axis.values) cases.push_back({{axis.key, v}});
    results.emplace(std::vector<sweep::SweepAxis>{axis}, cases, columns);
    for (std::size_t i = 0; i < cases.size(); ++i) results->set_name(i, "case_00" + std::to_string(i));
    const fs::path& root = folder.path;
    record(0, write_case(root, "case_000", summary("ok", true, 4, 1.25)), 0);
    // Ran to max_iterations without meeting the tolerance: the program exits with 0.
    record(1, write_case(root, "case_001", summary("ok", false, 1, 1.5)), 0);
    record(2, write_case(root, "case_002", summary("ok", true, 5, 2.0)), 0);
    record(
        3, write_case(root, "case_003", summary("failed", false, 2, 1.75, "coupling iteration 3 failed: singular")), 1);
    record(4,
                        write_case(root, "case_004",
                                   summary("interrupted", false, 1, 1.1, "interrupted after coupling iteration 1")),
                        1);
    results->record_not_run(5);
  }
  // A finished case read from its folder and recorded, as the sweep does; what was read.
  sweep::CaseResult record(std::size_t index, const fs::path& case_dir, int exit_code) {
    sweep::CaseResult r = sweep::read_case_result("case_00" + std::to_string(index), case_dir, exit_code, columns);
    results->set_result(index, r);
    return r;
  }
  const std::vector<std::string> columns{"flow.regions.seal.normalised_conductivity"};
  sweep::SweepAxis axis{"flow.boundary[0].head", {"5", "10", "15", "20", "25", "30"}};
  Folder folder;
  std::optional<sweep::SweepResults> results;
};

TEST_F(SweepResultsTest, EachCaseSaysHowItEnded) {
  const std::string csv = results->csv_text();
  EXPECT_NE(csv.find("case_000,5,ok,true,4,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("case_001,10,not converged,false,1,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("the coupling loop did not converge in 1 iteration(s)"), std::string::npos) << csv;
  EXPECT_NE(csv.find("case_002,15,ok,true,5,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("case_003,20,failed,false,2,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("coupling iteration 3 failed: singular"), std::string::npos) << csv;
  EXPECT_NE(csv.find("case_004,25,interrupted,false,1,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("case_005,30,not run,"), std::string::npos) << csv;

  const auto counts = results->count_by_status();
  EXPECT_EQ(counts[static_cast<std::size_t>(sweep::CaseStatus::ok)], 2u);
  EXPECT_EQ(counts[static_cast<std::size_t>(sweep::CaseStatus::not_converged)], 1u);
  EXPECT_EQ(counts[static_cast<std::size_t>(sweep::CaseStatus::failed)], 1u);
  EXPECT_EQ(counts[static_cast<std::size_t>(sweep::CaseStatus::interrupted)], 1u);
  EXPECT_EQ(counts[static_cast<std::size_t>(sweep::CaseStatus::not_run)], 1u);
  EXPECT_EQ(results->count_not_ok(), 4u);
  EXPECT_EQ(results->describe_not_ok(), "1 not converged, 1 failed, 1 interrupted, 1 not run");
}

// A case a signal ended before it wrote its summary is interrupted; any other exit without a
// summary is a failure, whose message points at the log.
TEST_F(SweepResultsTest, ACaseWithoutSummaryIsInterruptedOrFailed) {
  const fs::path killed = write_case(folder.path, "case_003", "");
  EXPECT_EQ(record(3, killed, 128 + SIGTERM).status, sweep::CaseStatus::interrupted);
  const fs::path crashed = write_case(folder.path, "case_004", "", "error: cannot mesh the domain\n");
  const sweep::CaseResult r = record(4, crashed, 128 + SIGSEGV);
  EXPECT_EQ(r.status, sweep::CaseStatus::failed);
  EXPECT_NE(r.message.find("exit code 139: cannot mesh the domain"), std::string::npos) << r.message;
  // A summary that says "ok" from a run that exited with an error is not taken as a result.
  const fs::path odd = write_case(folder.path, "case_000", summary("ok", true, 4, 1.25));
  EXPECT_EQ(record(0, odd, 1).status, sweep::CaseStatus::failed);
}

// A failed or interrupted case has no value: its summary.json holds the last good state it
// reached (here K/K_m 1.75 and 1.1), whose numbers are no answer. Its cells are empty, and
// the plot marks it with a cross on the x axis, with a legend entry, rather than leave it out.
TEST_F(SweepResultsTest, FailedAndInterruptedCasesHaveNoValue) {
  const std::string csv = results->csv_text();
  EXPECT_NE(csv.find("case_003,20,failed,false,2,,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("case_004,25,interrupted,false,1,,"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("1.75"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("1.1"), std::string::npos) << csv;
  const sweep::SweepPlot plot = results->plot_spec("Seal");
  EXPECT_EQ(plot.spec.marks_x, (std::vector<double>{20.0, 25.0}));
  EXPECT_EQ(plot.spec.marks_label, "failed or interrupted: no value");
  const fs::path png = folder.path / "sweep_marks.png";
  results->plot(png, "Seal");
  EXPECT_GT(fs::file_size(png), 1000u);
  // Only failed cases: the legend says so; with no case giving a value the crosses are drawn alone.
  std::vector<std::vector<hydrodda::scenario::Override>> cases{{{axis.key, "5"}}, {{axis.key, "10"}}};
  sweep::SweepResults failed_only(std::vector<sweep::SweepAxis>{{axis.key, {"5", "10"}}}, cases, columns);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    failed_only.set_name(i, "case_00" + std::to_string(i));
    failed_only.set_result(i, sweep::read_case_result("case_003", folder.path / "case_003", 1, columns));
  }
  const sweep::SweepPlot crosses = failed_only.plot_spec("Seal");
  EXPECT_TRUE(crosses.spec.series.empty());
  EXPECT_EQ(crosses.spec.marks_label, "failed: no value");
  const fs::path alone = folder.path / "sweep_failed.png";
  failed_only.plot(alone, "Seal");
  EXPECT_GT(fs::file_size(alone), 1000u);
}

// The converged cases make the line; the unconverged one is a hollow marker off it; the failed
// and interrupted ones are crosses (above), the unstarted one is not drawn.
TEST_F(SweepResultsTest, OnlyConvergedCasesMakeTheLine) {
  const sweep::SweepPlot plot = results->plot_spec("Seal");
  ASSERT_EQ(plot.spec.series.size(), 1u) << plot.why_not;
  const auto& s = plot.spec.series[0];
  EXPECT_EQ(s.x, (std::vector<double>{5.0, 10.0, 15.0}));
  EXPECT_EQ(s.y, (std::vector<double>{1.25, 1.5, 2.0}));
  EXPECT_EQ(s.open, (std::vector<bool>{false, true, false}));
  EXPECT_EQ(plot.spec.open_label, "not converged");
  EXPECT_EQ(plot.spec.x_label, "head (m)");  // no boundary names given: no owner
  EXPECT_EQ(plot.spec.y_label, "K_eff / K_matrix of seal");
  const fs::path png = folder.path / "sweep.png";
  results->plot(png, "Seal");
  EXPECT_GT(fs::file_size(png), 1000u);
}

}  // namespace
