#include "cli/resumed_run.hpp"

#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>

#include "cli/scenario_loading.hpp"

namespace hydrodda::cli {

namespace fs = std::filesystem;

std::optional<std::string> read_text_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return text.str();
}

std::optional<ResumedRun> open_resumed_run(const fs::path& directory) {
  const std::string dir = directory.string();
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) {
    spdlog::error("--resume {}: no such run folder", dir);
    return std::nullopt;
  }
  const fs::path checkpoint_file = directory / "checkpoint.bin";
  if (!fs::exists(checkpoint_file, ec)) {
    spdlog::error("--resume {}: the folder holds no checkpoint.bin, so there is nothing to resume (coupled runs "
                  "write one after each coupling iteration)",
                  dir);
    return std::nullopt;
  }
  const std::optional<std::string> bytes = read_text_file(checkpoint_file);
  if (!bytes) {
    spdlog::error("--resume {}: cannot read {}", dir, checkpoint_file.string());
    return std::nullopt;
  }
  ResumedRun run;
  try {
    run.checkpoint = output::decode_checkpoint(*bytes);
  } catch (const output::CheckpointError& e) {
    spdlog::error("{}: {}", checkpoint_file.string(), e.what());
    return std::nullopt;
  }
  const fs::path copy = directory / "scenario.toml";
  const std::optional<std::string> text = read_text_file(copy);
  if (!text) {
    spdlog::error("--resume {}: cannot read {}, the copy of the scenario the run started with", dir, copy.string());
    return std::nullopt;
  }
  if (output::hash_text(*text) != run.checkpoint.scenario_hash) {
    spdlog::error("{} differs from the scenario the run started with; a resumed run must use the same model "
                  "(start a new run to change it)",
                  copy.string());
    return std::nullopt;
  }
  // Parsed as the original file, so that relative paths (mesh.file) resolve as they did.
  std::optional<scenario::Scenario> scenario = load_scenario_text(*text, run.checkpoint.scenario_file);
  if (!scenario) return std::nullopt;
  if (!scenario->mechanics || !scenario->flow) {
    spdlog::error("--resume {}: only coupled runs ([mechanics] and [flow]) can be resumed", dir);
    return std::nullopt;
  }
  const int done = run.checkpoint.coupling.iterations;
  if (run.checkpoint.converged) {
    spdlog::error("--resume {}: the run already converged at coupling iteration {}; nothing to resume", dir, done);
    return std::nullopt;
  }
  if (done >= scenario->coupling.max_iterations) {
    spdlog::error("--resume {}: the run used all {} coupling iterations (coupling.max_iterations) without "
                  "converging; nothing to resume",
                  dir, done);
    return std::nullopt;
  }
  run.scenario = std::move(*scenario);
  run.scenario_text = *text;
  return run;
}

}  // namespace hydrodda::cli
