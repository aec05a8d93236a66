// `hydrodda breach`: its options read, the search run by breach/, its verdict printed and
// turned into an exit code.

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <string>

#include "breach/breach.hpp"
#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/scenario_loading.hpp"
#include "output/run_folder.hpp"
#include "run/threads.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::cli {

int breach_command(const BreachOptions& options) {
  if (!load_scenario(options.scenario)) return kBadInput;
  breach::BreachJob job;
  job.scenario = options.scenario;
  job.keys = options.keys;
  job.search = {.from = options.from, .to = options.to, .steps = options.steps, .tolerance = options.tolerance,
                .converged_only = options.converged_only};
  job.directory = options.output.value_or(std::filesystem::path("out") / (options.scenario.stem().string() + "-breach"));
  job.overwrite = options.overwrite;
  breach::BreachOutcome outcome;
  try {
    if (options.limit) job.limit = breach::parse_limit(*options.limit);
    breach::check_settings(job.search);
    run::use_threads(options.threads, /*spare_busy_machine=*/true);
    outcome = breach::run_breach(job, interrupt_requested);
  } catch (const scenario::ScenarioError& e) {
    print_scenario_errors(options.scenario, e);
    return kBadInput;
  } catch (const std::invalid_argument& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  } catch (const output::RunFolderError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    spdlog::error("the breach search failed: {}", e.what());
    return kRunFailed;
  }
  spdlog::info("{}; results in {}", outcome.verdict, outcome.folder.string());
  // A search that could not bracket the breach it was asked for has no answer to give.
  if (outcome.search.interrupted) return kRunFailed;
  if (outcome.search.broken && !outcome.search.held) return kRunFailed;
  return kSuccess;
}

}  // namespace hydrodda::cli
