#pragma once
// The subcommands. Each returns the program's exit code (see app.hpp).

#include <filesystem>
#include <optional>

#include "cli/progress.hpp"

namespace hydrodda::cli {

struct RunOptions {
  std::filesystem::path scenario;               // empty with --resume
  std::optional<std::filesystem::path> resume;  // --resume DIR: continue the coupled run in DIR
  std::optional<std::filesystem::path> output;  // -o: overrides output.directory
  bool overwrite = false;
  std::optional<int> stop_after;  // --stop-after N: a coupled run stops after iteration N, resumable
  Verbosity verbosity = Verbosity::Normal;
};

int check_command(const std::filesystem::path& scenario);
int run_command(const RunOptions& options);

}  // namespace hydrodda::cli
