#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/runs.hpp"
#include "cli/scenario_loading.hpp"
#include "output/run_folder.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::cli {

namespace {

void write_summary(const output::RunFolder& folder, const output::RunSummary& summary) {
  folder.write("summary.json", output::format_summary(summary));
}

// A run that stopped: summary.json says so (converged = false, what failed), exit code 1.
int report_failure(const output::RunFolder& folder, Progress& progress, const std::string& what,
                   output::RunSummary summary) {
  progress.finish();
  summary.converged = false;
  summary.status = "failed";
  summary.message = what;
  write_summary(folder, summary);
  spdlog::error("{}; the last good state is in {}", what, folder.path().string());
  return kRunFailed;
}

}  // namespace

int run_command(const RunOptions& options) {
  const auto scenario = load_scenario(options.scenario);
  if (!scenario) return kBadInput;
  const std::filesystem::path directory = options.output.value_or(scenario->output.directory);
  const auto policy = options.overwrite ? output::ExistingFolder::Overwrite : output::ExistingFolder::Refuse;
  std::optional<output::RunFolder> folder;
  try {
    folder.emplace(directory, policy);
  } catch (const output::RunFolderError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  }
  install_interrupt_handlers();
  Progress progress(options.verbosity, ::isatty(STDERR_FILENO) == 1);
  const RunContext context{*scenario, *folder, progress};
  try {
    const output::RunSummary summary = scenario->mechanics && scenario->flow ? run_coupled(context)
                                              : scenario->mechanics   ? run_mechanics(context)
                                                                      : run_flow(context);
    write_summary(*folder, summary);
    progress.finish();
    spdlog::info("{}; results in {}", summary.converged ? "finished" : "not converged",
                 folder->path().string());
    return kSuccess;
  } catch (const scenario::ScenarioError& e) {
    // Found while building the model: still bad input.
    progress.finish();
    for (const scenario::Diagnostic& d : e.diagnostics()) spdlog::error("{}", d.format());
    return kBadInput;
  } catch (const RunFailure& failure) {
    return report_failure(*folder, progress, failure.what(), failure.summary());
  } catch (const std::exception& e) {
    // A failure before any result exists (meshing, a singular system): reported, never hidden.
    output::RunSummary summary;
    summary.title = scenario->title;
    summary.scenario = scenario->file.string();
    return report_failure(*folder, progress, e.what(), summary);
  }
}

}  // namespace hydrodda::cli
