#pragma once
// Opening a run folder to continue its coupled run (run --resume DIR): the checkpoint and the
// copy of the scenario the run started with, both checked before anything is run.

#include <filesystem>
#include <optional>
#include <string>

#include "output/checkpoint.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::cli {

struct ResumedRun {
  scenario::Scenario scenario;  // read from DIR/scenario.toml, paths resolved as at the start
  std::string scenario_text;
  output::RunCheckpoint checkpoint;
};

// Reads DIR/checkpoint.bin and DIR/scenario.toml. Prints why and returns nothing when the run
// cannot be continued: no checkpoint, a damaged one, a scenario copy edited since the start,
// or a run that already converged or used all its coupling iterations.
std::optional<ResumedRun> open_resumed_run(const std::filesystem::path& directory);

// The whole content of a file, or nothing when it cannot be read.
std::optional<std::string> read_text_file(const std::filesystem::path& file);

}  // namespace hydrodda::cli
