#pragma once
// Opening a run folder to continue its coupled (steady or transient) or transient flow-only run (run --resume DIR): the checkpoint and the
// copy of the scenario the run started with, both checked before anything is run.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "output/checkpoint.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::run {

// What a run's folder holds to continue it: its checkpoint and its scenario's text. A transient
// flow-only run's checkpoint is `transient`, a coupled transient run's `coupled_transient`;
// `checkpoint` then holds its scenario's hash, file and input files alone.
struct SavedRun {
  std::string scenario_text;
  output::RunCheckpoint checkpoint;
  std::optional<output::TransientCheckpoint> transient;
  std::optional<output::CoupledTransientCheckpoint> coupled_transient;
};

struct ResumedRun {
  std::filesystem::path folder;
  scenario::Scenario scenario;  // read from DIR/scenario.toml, paths resolved as at the start
  std::string scenario_text;
  output::RunCheckpoint checkpoint;
  std::optional<output::TransientCheckpoint> transient;  // a transient flow-only run's
  std::optional<output::CoupledTransientCheckpoint> coupled_transient;  // a coupled transient run's
};

// Every file the scenario names (geometry.fractures_file, mesh.file) with the hash of its
// content, for the checkpoint. Throws InputError naming a file that cannot be read.
std::vector<output::InputFile> hash_input_files(const scenario::Scenario& scenario);

// Reads DIR/checkpoint.bin and DIR/scenario.toml. Throws InputError saying why when there is no
// checkpoint, when it is damaged, or when the scenario copy or a file it names
// (RunCheckpoint::input_files) was edited, moved or deleted since the start.
SavedRun read_saved_run(const std::filesystem::path& directory);

// Throws InputError when the run cannot be continued: it is neither a coupled run nor a
// transient flow-only run, its checkpoint is of another kind of run than its scenario, or it
// already converged, used all its coupling iterations, reached its end_time or failed at its
// floor of step lengths and its summary.json says so. One whose summary.json does not (the disk filled as
// it was written) is resumed to write it.
void check_resumable(const std::filesystem::path& directory, const scenario::Scenario& scenario,
                     const SavedRun& saved);

// Both of the above, the scenario parsed as the original file (so that relative paths such as
// mesh.file resolve as they did); a scenario copy that does not parse throws ScenarioError.
ResumedRun open_resumed_run(const std::filesystem::path& directory);

}  // namespace hydrodda::run
