// `hydrodda sweep`: its options read, its cases prepared and checked, then run by sweep/ and
// its outcome turned into messages and an exit code.

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <optional>
#include <string>
#include <algorithm>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/scenario_loading.hpp"
#include "output/run_folder.hpp"
#include "run/threads.hpp"
#include "sweep/cases.hpp"
#include "sweep/preparation.hpp"
#include "sweep/ranks.hpp"
#include "sweep/sweep.hpp"

namespace hydrodda::cli {

namespace fs = std::filesystem;

namespace {

void print_error(const std::string& message) { std::fputs(fmt::format("error: {}\n", message).c_str(), stderr); }

// The columns sweep.csv holds: those asked for, else each flow region's effective conductivity.
std::vector<std::string> choose_columns(const SweepOptions& options, const sweep::Preparation& preparation) {
  std::vector<std::string> columns = options.columns;
  if (columns.empty())
    for (const std::string& region : preparation.region_names)
      columns.push_back(fmt::format("flow.regions.{}.effective_conductivity", region));
  return columns;
}

}  // namespace

int sweep_command(const SweepOptions& options, sweep::SweepRanks& ranks) {
  const auto base = load_scenario(options.scenario);
  if (!base) return kBadInput;
  sweep::SweepJob job;
  job.scenario = options.scenario;
  job.zip = options.zip;
  int threads = 1;  // of all the cases at a time
  try {
    threads = run::use_threads(options.threads, /*spare_busy_machine=*/false);
    for (const std::string& set : options.sets) job.axes.push_back(sweep::parse_sweep_axis(set));
    job.cases = options.zip ? sweep::zip_cases(job.axes) : sweep::enumerate_cases(job.axes);
  } catch (const std::exception& e) {  // std::invalid_argument, run::InputError
    print_error(e.what());
    return kBadInput;
  }
  job.directory = options.output.value_or(fs::path("out") / (options.scenario.stem().string() + "-sweep"));
  const sweep::Preparation preparation =
      sweep::prepare_cases(options.scenario, job.directory, job.cases, *base, interrupt_requested);
  if (preparation.interrupted) {
    print_error(fmt::format("interrupted while checking the cases ({} of {} checked); nothing was run or written",
                            preparation.cases.size(), job.cases.size()));
    return kRunFailed;
  }
  if (!preparation.errors.empty()) {
    for (const std::string& line : preparation.errors) print_error(line);
    std::fputs(fmt::format("{}: the sweep was not started\n", options.scenario.string()).c_str(), stderr);
    return kBadInput;
  }
  job.columns = choose_columns(options, preparation);
  job.boundary_names = sweep::boundary_names_of(*base);
  job.jobs = options.jobs.value_or(threads);
  job.case_threads = std::max(1, threads / (ranks.size() > 1 ? ranks.size() : job.jobs));
  job.overwrite = options.overwrite;
  job.title = options.title.value_or(base->title);

  sweep::SweepOutcome outcome;
  try {
    outcome = sweep::run_sweep(job, preparation.cases, ranks, interrupt_requested);
  } catch (const output::RunFolderError& e) {
    print_error(e.what());
    return kBadInput;
  } catch (const sweep::SweepFailed& e) {
    print_error(e.what());
    return kRunFailed;
  }
  // A case that did not converge counts as failed here: its numbers are not a result, and a
  // script that checks the exit code must not take them for one.
  if (outcome.not_ok > 0) {
    spdlog::error("{} of {} case(s) gave no converged result ({}); see {}", outcome.not_ok, outcome.cases,
                  outcome.describe_not_ok, outcome.table.string());
    return kRunFailed;
  }
  spdlog::info("all {} case(s) converged; results in {}", outcome.cases, outcome.table.string());
  return kSuccess;
}

int sweep_on_ranks(const SweepOptions& options) {
  std::optional<sweep::SweepRanks> ranks;
  try {
    ranks.emplace(interrupt_requested);
  } catch (const std::runtime_error& e) {
    spdlog::error("sweep: {}", e.what());
    return kBadInput;
  }
  if (ranks->rank() != 0) return ranks->serve();
  if (ranks->size() > 1 && options.jobs) {
    spdlog::error("sweep: --jobs does not apply under mpirun, where each of the {} ranks runs one case at a time; "
                  "set the number of ranks with mpirun -n", ranks->size());
    ranks->finish(kBadInput);
    return kBadInput;
  }
  const int code = sweep_command(options, *ranks);
  ranks->finish(code);
  return code;
}

}  // namespace hydrodda::cli
