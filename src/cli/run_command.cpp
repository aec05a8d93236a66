#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdio>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/scenario_loading.hpp"
#include "output/run_folder.hpp"

namespace hydrodda::cli {

namespace {
// A part of the model whose engine is not built in yet: an explicit error, never a silent zero.
std::optional<std::string> missing_engine(const scenario::Scenario& s) {
  if (s.mechanics) return "mechanics is not available yet";
  if (s.flow) return "flow is not available yet";
  return std::nullopt;
}
}  // namespace

int run_command(const RunOptions& options) {
  const auto scenario = load_scenario(options.scenario);
  if (!scenario) return kBadInput;
  const std::filesystem::path directory = options.output.value_or(scenario->output.directory);
  const auto policy = options.overwrite ? output::ExistingFolder::Overwrite : output::ExistingFolder::Refuse;
  try {
    output::RunFolder::check_available(directory, policy);
  } catch (const output::RunFolderError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  }
  if (auto missing = missing_engine(*scenario)) {
    spdlog::error("{}: {}", options.scenario.string(), *missing);
    return kRunFailed;
  }
  try {
    output::RunFolder folder(directory, policy);
    Progress progress(options.verbosity, ::isatty(STDERR_FILENO) == 1);
    (void)progress;
    spdlog::error("no engine can run {}", options.scenario.string());
    return kRunFailed;
  } catch (const output::RunFolderError& e) {
    spdlog::error("{}", e.what());
    return kBadInput;
  }
}

}  // namespace hydrodda::cli
