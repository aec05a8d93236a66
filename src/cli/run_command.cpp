#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/hold_points.hpp"
#include "cli/interrupt.hpp"
#include "cli/scenario_loading.hpp"
#include "output/run_folder.hpp"
#include "run/resumed_run.hpp"
#include "run/run.hpp"
#include "run/threads.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::cli {

namespace {

// The run folder to continue (run --resume DIR), its scenario read and logged as a new run's.
std::optional<run::ResumedRun> open_resumed_run(const std::filesystem::path& directory) {
  run::SavedRun saved = run::read_saved_run(directory);
  // Parsed as the original file, so that relative paths (mesh.file) resolve as they did.
  std::optional<scenario::Scenario> scenario = load_scenario_text(saved.scenario_text, saved.checkpoint.scenario_file);
  if (!scenario) return std::nullopt;
  run::check_resumable(directory, *scenario, saved);
  return run::ResumedRun{directory, std::move(*scenario), std::move(saved.scenario_text), std::move(saved.checkpoint),
                         std::move(saved.transient), std::move(saved.coupled_transient)};
}

// The exit code of a run that went as far as running, and the line that says how it ended.
int report(const run::RunResult& result) {
  const std::string folder = result.folder.string();
  switch (result.status) {
    case run::RunStatus::stopped:
      spdlog::info("{}; continue with: hydrodda run --resume {}", result.message, folder);
      return kSuccess;
    case run::RunStatus::finished:
      // A coupled run (the one kind with outside_mesh) says how many passes its loop took.
      if (result.converged && result.summary.outside_mesh && !result.summary.time)
        spdlog::info("converged in {} coupling iteration(s); results in {}", result.iterations, folder);
      else
        spdlog::info("{}; results in {}", result.converged ? "finished" : "not converged", folder);
      return kSuccess;
    case run::RunStatus::interrupted:
    case run::RunStatus::failed:
    case run::RunStatus::no_equilibrium:
      break;
  }
  if (result.good_state_kept)
    spdlog::error("{}; the last good state is in {}", result.message, folder);
  else
    spdlog::error("{}; no good state was kept (summary.json holds none, or values that are not finite, as null); "
                  "what was written is in {}",
                  result.message, folder);
  return kRunFailed;
}

}  // namespace

int run_command(const RunOptions& options) {
  try {
    run::use_threads(options.threads, /*spare_busy_machine=*/true);
  } catch (const run::InputError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  }
  Progress progress(options.verbosity, ::isatty(STDERR_FILENO) == 1);
  std::filesystem::path folder;  // removed when an interrupt while building the model leaves it empty
  run::Callbacks callbacks;
  callbacks.progress = [&](const run::ProgressReport& r) { progress.update(r.message); };
  callbacks.stop_requested = [] {
    pass_stop_check();
    return interrupt_requested();
  };
  callbacks.unstoppable_stage = [&](bool unstoppable) { set_exit_on_interrupt(unstoppable, folder); };
  try {
    std::optional<run::RunResult> result;
    if (options.resume) {
      const std::optional<run::ResumedRun> resumed = open_resumed_run(*options.resume);
      if (!resumed) return kBadInput;
      result = run::resume(*resumed, options.stop_after, callbacks);
    } else {
      const std::optional<scenario::Scenario> scenario = load_scenario(options.scenario);
      if (!scenario) return kBadInput;
      const run::RunOptions run_options{options.output.value_or(scenario->output.directory), options.overwrite,
                                        options.stop_after, std::nullopt, options.mesh_cache};
      std::error_code ec;
      if (!std::filesystem::exists(run_options.folder, ec)) folder = run_options.folder;
      result = run::run(*scenario, run_options, callbacks);
    }
    progress.finish();
    return report(*result);
  } catch (const scenario::ScenarioError& e) {
    // Found while building the model: bad input, and the run left no folder behind.
    progress.finish();
    for (const scenario::Diagnostic& d : e.diagnostics()) spdlog::error("{}", d.format());
    return kBadInput;
  } catch (const run::InputError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  } catch (const output::RunFolderError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  }
}

}  // namespace hydrodda::cli
