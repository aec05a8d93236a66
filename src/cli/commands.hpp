#pragma once
// The subcommands. Each returns the program's exit code (see app.hpp).

#include <filesystem>
#include <optional>

#include "cli/progress.hpp"

namespace hydrodda::cli {

struct RunOptions {
  std::filesystem::path scenario;
  std::optional<std::filesystem::path> output;  // -o: overrides output.directory
  bool overwrite = false;
  Verbosity verbosity = Verbosity::Normal;
};

int check_command(const std::filesystem::path& scenario);
int run_command(const RunOptions& options);

}  // namespace hydrodda::cli
