#include "run/resumed_run.hpp"

#include <fmt/format.h>

#include "run/run.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::run {

namespace fs = std::filesystem;

SavedRun read_saved_run(const fs::path& directory) {
  const std::string dir = directory.string();
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) throw InputError(fmt::format("--resume {}: no such run folder", dir));
  const fs::path checkpoint_file = directory / "checkpoint.bin";
  if (!fs::exists(checkpoint_file, ec))
    throw InputError(fmt::format("--resume {}: the folder holds no checkpoint.bin, so there is nothing to resume "
                                 "(coupled runs write one after each coupling iteration)",
                                 dir));
  const std::optional<std::string> bytes = read_text_file(checkpoint_file);
  if (!bytes) throw InputError(fmt::format("--resume {}: cannot read {}", dir, checkpoint_file.string()));
  SavedRun run;
  try {
    run.checkpoint = output::decode_checkpoint(*bytes);
  } catch (const output::CheckpointError& e) {
    throw InputError(fmt::format("{}: {}", checkpoint_file.string(), e.what()));
  }
  const fs::path copy = directory / "scenario.toml";
  const std::optional<std::string> text = read_text_file(copy);
  if (!text)
    throw InputError(
        fmt::format("--resume {}: cannot read {}, the copy of the scenario the run started with", dir, copy.string()));
  if (output::hash_text(*text) != run.checkpoint.scenario_hash)
    throw InputError(fmt::format("{} differs from the scenario the run started with; a resumed run must use the "
                                 "same model (start a new run to change it)",
                                 copy.string()));
  run.scenario_text = *text;
  return run;
}

void check_resumable(const fs::path& directory, const scenario::Scenario& scenario,
                     const output::RunCheckpoint& checkpoint) {
  const std::string dir = directory.string();
  if (!scenario.mechanics || !scenario.flow)
    throw InputError(fmt::format("--resume {}: only coupled runs ([mechanics] and [flow]) can be resumed", dir));
  const int done = checkpoint.coupling.iterations;
  if (checkpoint.converged)
    throw InputError(
        fmt::format("--resume {}: the run already converged at coupling iteration {}; nothing to resume", dir, done));
  if (done >= scenario.coupling.max_iterations)
    throw InputError(fmt::format("--resume {}: the run used all {} coupling iterations (coupling.max_iterations) "
                                 "without converging; nothing to resume",
                                 dir, done));
}

ResumedRun open_resumed_run(const fs::path& directory) {
  SavedRun saved = read_saved_run(directory);
  scenario::Scenario scenario = scenario::parse_scenario(saved.scenario_text, saved.checkpoint.scenario_file);
  check_resumable(directory, scenario, saved.checkpoint);
  return {directory, std::move(scenario), std::move(saved.scenario_text), std::move(saved.checkpoint)};
}

}  // namespace hydrodda::run
