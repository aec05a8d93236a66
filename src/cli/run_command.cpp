#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <filesystem>
#include <optional>
#include <string>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/resumed_run.hpp"
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
  // The scenario, its text and the folder: a new run's, or those of the run to continue.
  std::optional<ResumedRun> resumed;
  std::optional<scenario::Scenario> loaded;
  std::string scenario_text;
  std::filesystem::path directory;
  auto policy = options.overwrite ? output::ExistingFolder::Overwrite : output::ExistingFolder::Refuse;
  if (options.resume) {
    resumed = open_resumed_run(*options.resume);
    if (!resumed) return kBadInput;
    directory = *options.resume;
    policy = output::ExistingFolder::Overwrite;  // its own files, continued
  } else {
    loaded = load_scenario(options.scenario);
    if (!loaded) return kBadInput;
    const std::optional<std::string> text = read_text_file(options.scenario);
    if (!text) {
      spdlog::error("cannot read {}", options.scenario.string());
      return kBadInput;
    }
    scenario_text = *text;
    directory = options.output.value_or(loaded->output.directory);
  }
  const scenario::Scenario& scenario = resumed ? resumed->scenario : *loaded;
  if (options.stop_after && !(scenario.mechanics && scenario.flow)) {
    spdlog::error("--stop-after: only coupled runs ([mechanics] and [flow]) stop after an iteration");
    return kBadInput;
  }
  std::error_code ec;
  const bool folder_is_new = !std::filesystem::exists(directory, ec);
  std::optional<output::RunFolder> folder;
  try {
    folder.emplace(directory, policy);
  } catch (const output::RunFolderError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  }
  install_interrupt_handlers();
  Progress progress(options.verbosity, ::isatty(STDERR_FILENO) == 1);
  const RunContext context{scenario, *folder, progress, resumed ? resumed->scenario_text : scenario_text,
                           resumed ? &resumed->checkpoint : nullptr, options.stop_after};
  try {
    const output::RunSummary summary = scenario.mechanics && scenario.flow ? run_coupled(context)
                                       : scenario.mechanics               ? run_mechanics(context)
                                                                          : run_flow(context);
    write_summary(*folder, summary);
    progress.finish();
    if (summary.status == "stopped")
      spdlog::info("{}; continue with: hydrodda run --resume {}", summary.message, folder->path().string());
    else
      spdlog::info("{}; results in {}", summary.converged ? "finished" : "not converged", folder->path().string());
    return kSuccess;
  } catch (const scenario::ScenarioError& e) {
    // Found while building the model: still bad input, and bad input leaves no run folder
    // behind. Nothing has been written by then; a folder this run made is removed.
    progress.finish();
    for (const scenario::Diagnostic& d : e.diagnostics()) spdlog::error("{}", d.format());
    if (folder_is_new) std::filesystem::remove_all(directory, ec);
    return kBadInput;
  } catch (const RunFailure& failure) {
    return report_failure(*folder, progress, failure.what(), failure.summary());
  } catch (const std::exception& e) {
    // A failure before any result exists (meshing, a singular system): reported, never hidden.
    output::RunSummary summary;
    summary.title = scenario.title;
    summary.scenario = scenario.file.string();
    return report_failure(*folder, progress, e.what(), summary);
  }
}

}  // namespace hydrodda::cli
