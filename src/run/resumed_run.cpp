#include "run/resumed_run.hpp"

#include <fmt/format.h>

#include "output/summary_reading.hpp"
#include "run/run.hpp"
#include "run/transient_flow.hpp"
#include "scenario/load_times.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::run {

namespace fs = std::filesystem;

std::vector<output::InputFile> hash_input_files(const scenario::Scenario& s) {
  std::vector<output::InputFile> files;
  const auto add = [&](const char* key, const std::optional<fs::path>& file) {
    if (!file) return;
    const std::optional<std::string> text = read_text_file(*file);
    if (!text) throw InputError(fmt::format("cannot read {} ({})", file->string(), key));
    files.push_back({key, fs::absolute(*file).string(), output::hash_text(*text)});
  };
  if (s.geometry) add("geometry.fractures_file", s.geometry->fractures_file);
  if (s.mesh) add("mesh.file", s.mesh->file);
  return files;
}

namespace {

// Throws InputError naming the first file the scenario names that is not as the run read it.
void check_input_files(const fs::path& directory, const output::RunCheckpoint& checkpoint) {
  for (const output::InputFile& f : checkpoint.input_files) {
    const std::optional<std::string> text = read_text_file(f.path);
    if (!text)
      throw InputError(fmt::format("--resume {}: cannot read {} ({}), which the run read at its start; a resumed "
                                   "run must use the same model (restore the file, or start a new run)",
                                   directory.string(), f.path, f.key));
    if (output::hash_text(*text) != f.hash)
      throw InputError(fmt::format("--resume {}: {} ({}) changed since the run started; a resumed run must use the "
                                   "same model (restore the file, or start a new run to use the new one)",
                                   directory.string(), f.path, f.key));
  }
}

// DIR/summary.json records the end of a run that did `iterations` passes (status "ok", or
// "failed" once they were done); not when it is missing, unreadable, or of an earlier state.
bool summary_records_end(const fs::path& directory, int iterations) {
  try {
    const auto values = output::read_summary_values(directory / "summary.json", {"status", "iterations"});
    return (values[0] == "ok" || values[0] == "failed") && values[1] == std::to_string(iterations);
  } catch (const std::runtime_error&) {
    return false;
  }
}

}  // namespace

SavedRun read_saved_run(const fs::path& directory) {
  const std::string dir = directory.string();
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) throw InputError(fmt::format("--resume {}: no such run folder", dir));
  const fs::path checkpoint_file = directory / "checkpoint.bin";
  if (!fs::exists(checkpoint_file, ec))
    throw InputError(fmt::format("--resume {}: the folder holds no checkpoint.bin, so there is nothing to resume "
                                 "(coupled runs write one after each coupling iteration, transient runs at each output time "
                                 "and when interrupted)",
                                 dir));
  const std::optional<std::string> bytes = read_text_file(checkpoint_file);
  if (!bytes) throw InputError(fmt::format("--resume {}: cannot read {}", dir, checkpoint_file.string()));
  SavedRun run;
  try {
    if (output::is_transient_checkpoint(*bytes)) {
      run.transient = output::decode_transient_checkpoint(*bytes);
      run.checkpoint.scenario_hash = run.transient->scenario_hash;
      run.checkpoint.scenario_file = run.transient->scenario_file;
      run.checkpoint.input_files = run.transient->input_files;
    } else if (output::is_coupled_transient_checkpoint(*bytes)) {
      run.coupled_transient = output::decode_coupled_transient_checkpoint(*bytes);
      run.checkpoint.scenario_hash = run.coupled_transient->scenario_hash;
      run.checkpoint.scenario_file = run.coupled_transient->scenario_file;
      run.checkpoint.input_files = run.coupled_transient->input_files;
    } else {
      run.checkpoint = output::decode_checkpoint(*bytes);
    }
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
  check_input_files(directory, run.checkpoint);
  run.scenario_text = *text;
  return run;
}

namespace {

void check_transient_resumable(const fs::path& directory, const scenario::Scenario& scenario,
                               const output::TransientCheckpoint& checkpoint) {
  const std::string dir = directory.string();
  if (scenario.mechanics || !scenario.flow || !scenario.flow->transient)
    throw InputError(fmt::format("--resume {}: its checkpoint is a transient flow-only run's, its scenario is not", dir));
  const int planned = static_cast<int>(plan_step_times(*scenario.flow->transient, scenario::find_load_times(scenario)).size());
  if (checkpoint.steps == planned && summary_records_end(directory, planned))
    throw InputError(fmt::format("--resume {}: the run already reached its end_time ({:g} s); nothing to resume", dir,
                                 checkpoint.time));
}

void check_coupled_transient_resumable(const fs::path& directory, const scenario::Scenario& scenario,
                                       const output::CoupledTransientCheckpoint& checkpoint) {
  const std::string dir = directory.string();
  if (!scenario.mechanics || !scenario.flow || !scenario.flow->transient)
    throw InputError(fmt::format("--resume {}: its checkpoint is a coupled transient run's, its scenario is not", dir));
  if (!checkpoint.ended || !summary_records_end(directory, checkpoint.steps)) return;
  if (checkpoint.time >= scenario.flow->transient->end_time)
    throw InputError(fmt::format("--resume {}: the run already reached its end_time ({:g} s); nothing to resume", dir,
                                 checkpoint.time));
  throw InputError(fmt::format("--resume {}: the run ended not converged at t = {:g} s, its step there failed at the "
                               "floor of its length (summary.json says why); nothing to resume",
                               dir, checkpoint.time));
}

}  // namespace

void check_resumable(const fs::path& directory, const scenario::Scenario& scenario, const SavedRun& saved) {
  if (saved.transient) return check_transient_resumable(directory, scenario, *saved.transient);
  if (saved.coupled_transient) return check_coupled_transient_resumable(directory, scenario, *saved.coupled_transient);
  const output::RunCheckpoint& checkpoint = saved.checkpoint;
  const std::string dir = directory.string();
  if (!scenario.mechanics || !scenario.flow)
    throw InputError(fmt::format("--resume {}: only coupled runs ([mechanics] and [flow]) and transient flow-only runs "
                                 "([flow.transient]) can be resumed",
                                 dir));
  if (scenario.flow->transient)
    throw InputError(fmt::format("--resume {}: its checkpoint is a steady coupled run's, its scenario has "
                                 "[flow.transient]",
                                 dir));
  const int done = checkpoint.coupling.iterations;
  const bool ended = checkpoint.converged || done >= scenario.coupling.max_iterations;
  if (!ended || !summary_records_end(directory, done)) return;
  if (checkpoint.converged)
    throw InputError(
        fmt::format("--resume {}: the run already converged at coupling iteration {}; nothing to resume", dir, done));
  throw InputError(fmt::format("--resume {}: the run used all {} coupling iterations (coupling.max_iterations) "
                               "without converging; nothing to resume",
                               dir, done));
}

ResumedRun open_resumed_run(const fs::path& directory) {
  SavedRun saved = read_saved_run(directory);
  scenario::Scenario scenario = scenario::parse_scenario(saved.scenario_text, saved.checkpoint.scenario_file);
  check_resumable(directory, scenario, saved);
  return {directory, std::move(scenario), std::move(saved.scenario_text), std::move(saved.checkpoint),
          std::move(saved.transient), std::move(saved.coupled_transient)};
}

}  // namespace hydrodda::run
