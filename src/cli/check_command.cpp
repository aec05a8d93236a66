#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/scenario_loading.hpp"
#include "run/run.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::cli {

int check_command(const std::filesystem::path& file) {
  const auto scenario = load_scenario(file);
  if (!scenario) return kBadInput;
  std::string geometry;
  try {
    geometry = run::check_model(*scenario);
  } catch (const scenario::ScenarioError& e) {
    print_scenario_errors(file, e);
    return kBadInput;
  }
  std::string description = describe(*scenario);
  if (!geometry.empty()) description += ", " + geometry;
  std::fputs(fmt::format("{}: OK ({})\n", file.string(), description).c_str(), stdout);
  return kSuccess;
}

}  // namespace hydrodda::cli
