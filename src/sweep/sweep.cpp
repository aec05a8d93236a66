#include "sweep/sweep.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <optional>

#include "output/run_folder.hpp"
#include "run/run.hpp"
#include "sweep/child_processes.hpp"
#include "sweep/results.hpp"

namespace hydrodda::sweep {

namespace fs = std::filesystem;

namespace {

// The cases' shared meshes (run --mesh-cache): cases of one geometry and mesh settings mesh once.
constexpr const char* kMeshCache = "mesh-cache";

// The lines of a case's run.log that are warnings ("warning: ..."); 0 without the file.
int count_warnings(const fs::path& log) {
  std::ifstream in(log);
  int count = 0;
  for (std::string line; std::getline(in, line);) count += line.rfind("warning: ", 0) == 0;
  return count;
}

// The sweep's folder with each case's scenario file, no result of an earlier sweep in it.
output::RunFolder write_case_folders(const SweepJob& job, const std::vector<PreparedCase>& prepared,
                                     const std::function<bool()>& stop_requested) {
  output::RunFolder folder(job.directory,
                           job.overwrite ? output::ExistingFolder::Overwrite : output::ExistingFolder::Refuse);
  // Meshes live as long as the sweep: none made by an earlier sweep (an older program) is read.
  run::clear_mesh_cache(job.directory / kMeshCache);
  for (const PreparedCase& c : prepared) {
    if (stop_requested()) break;  // no case will start: each is listed as not run
    const output::RunFolder case_folder(folder.subfolder(c.name), output::ExistingFolder::Overwrite);
    case_folder.write("scenario.toml", c.text);
    fs::remove(case_folder.file("summary.json"));  // an earlier sweep's result must not be read as this one's
  }
  return folder;
}

// Each case a child `hydrodda run` of this program into its folder, sharing the mesh cache.
SweepPlan plan_cases(const SweepJob& job, const std::vector<PreparedCase>& prepared) {
  const fs::path program = fs::read_symlink("/proc/self/exe");
  SweepPlan plan{{}, {}, job.columns};
  for (const PreparedCase& c : prepared) {
    const fs::path case_dir = job.directory / c.name;
    plan.commands.push_back({{program.string(), "-q", "run", (case_dir / "scenario.toml").string(), "-o",
                              case_dir.string(), "--overwrite", "--mesh-cache", (job.directory / kMeshCache).string(),
                              "--threads", std::to_string(job.case_threads)},
                             case_dir / "run.log"});
    plan.folders.push_back(case_dir);
  }
  return plan;
}

// The line logged as a case ends: its values, status, message, warnings and the count so far.
void log_case(const SweepJob& job, const PreparedCase& c, std::size_t index, const CaseResult& r,
              std::size_t finished, int ranks, int rank) {
  // A case's warnings (a mesh that does not resolve what it must, blocks off the mesh)
  // qualify its numbers: say that its run.log has some.
  const int warnings = count_warnings(job.directory / c.name / "run.log");
  const std::string line = fmt::format(
      "{} ({}): {}{}{}  [{}/{}{}]", c.name, describe_case(job.cases[index]), status_name(r.status),
      r.message.empty() ? "" : ": " + r.message,
      warnings > 0 ? fmt::format(" ({} warning(s) in {}/run.log)", warnings, c.name) : "", finished,
      job.cases.size(), ranks > 1 ? fmt::format(", rank {}", rank) : "");
  if (r.status == CaseStatus::ok) spdlog::info("{}", line);
  else if (r.status == CaseStatus::failed) spdlog::error("{}", line);
  else spdlog::warn("{}", line);
}

// sweep.csv with the cases never started, and sweep.png.
void finish_table(const SweepJob& job, const output::RunFolder& folder, SweepResults& results,
                  const std::vector<std::size_t>& never_started) {
  for (std::size_t index : never_started) results.record_not_run(index);
  folder.write("sweep.csv", results.csv_text());
  results.plot(job.directory / "sweep.png", job.title);
}

}  // namespace

SweepOutcome run_sweep(const SweepJob& job, const std::vector<PreparedCase>& prepared, SweepRanks& ranks,
                       const std::function<bool()>& stop_requested) {
  const output::RunFolder folder = write_case_folders(job, prepared, stop_requested);
  const SweepPlan plan = plan_cases(job, prepared);
  const int jobs = ranks.size() > 1 ? ranks.size() : job.jobs;
  spdlog::info("sweep of {}: {} case(s), {} at a time{}, in {}", job.scenario.string(), job.cases.size(), jobs,
               ranks.size() > 1 ? " (one per MPI rank)" : "", job.directory.string());

  SweepResults results(job.axes, job.cases, job.columns, job.zip);
  for (std::size_t i = 0; i < prepared.size(); ++i) results.set_name(i, prepared[i].name);
  results.set_boundary_names(job.boundary_names);
  std::size_t finished = 0;
  std::vector<std::size_t> never_started;
  const auto case_finished = [&](std::size_t index, const CaseResult& r, int rank) {
    results.set_result(index, r);
    log_case(job, prepared[index], index, r, ++finished, ranks.size(), rank);
    folder.write("sweep.csv", results.csv_text());
  };
  try {
    if (ranks.size() > 1) {
      never_started = ranks.run_cases(plan, case_finished);
    } else {
      const auto child_finished = [&](std::size_t index, int exit_code) {
        case_finished(index,
                      read_case_result(prepared[index].name, plan.folders[index], exit_code, job.columns,
                                       stop_requested()),
                      0);
      };
      never_started = run_child_processes(plan.commands, jobs, child_finished, stop_requested);
    }
  } catch (const std::exception& e) {
    const std::string message = e.what();
    try {
      folder.write("sweep.csv", results.csv_text());
    } catch (const std::exception&) {  // the first failure is the news
    }
    throw SweepFailed(message);
  }
  try {
    finish_table(job, folder, results, never_started);
  } catch (const std::exception& e) {
    throw SweepFailed(e.what());
  }
  return {job.cases.size(), results.count_not_ok(), results.describe_not_ok(), job.directory / "sweep.csv"};
}

}  // namespace hydrodda::sweep
