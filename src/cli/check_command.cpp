#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "cli/app.hpp"
#include "cli/commands.hpp"
#include "cli/scenario_loading.hpp"
#include "run/preview.hpp"
#include "run/run.hpp"
#include "scenario/diagnostics.hpp"

namespace hydrodda::cli {

int check_command(const std::filesystem::path& file, const std::optional<std::filesystem::path>& figure) {
  if (figure)
    if (const std::string problem = run::find_figure_path_problem(*figure); !problem.empty()) {
      std::fputs(fmt::format("error: --figure {}: {}\n", figure->string(), problem).c_str(), stderr);
      return kBadInput;
    }
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
  if (figure) {
    try {
      run::draw_preview(*scenario, *figure);
    } catch (const std::exception& e) {
      std::fputs(fmt::format("error: --figure {}: {}\n", figure->string(), e.what()).c_str(), stderr);
      return kBadInput;
    }
    std::fputs(fmt::format("preview drawn: {}\n", figure->string()).c_str(), stdout);
  }
  return kSuccess;
}

}  // namespace hydrodda::cli
