#pragma once
// Reading a scenario for a subcommand: errors printed all together, defaults logged.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "scenario/diagnostics.hpp"
#include "scenario/scenario.hpp"

namespace hydrodda::cli {

// The scenario, or nothing after every error has been printed to stderr.
std::optional<scenario::Scenario> load_scenario(const std::filesystem::path& file);
// The same from text that `file` held (the base of relative paths, and named in messages).
std::optional<scenario::Scenario> load_scenario_text(std::string_view text, const std::filesystem::path& file);

// Prints every error of `error` to stderr, then "<file>: N error(s)".
void print_scenario_errors(const std::filesystem::path& file, const scenario::ScenarioError& error);

// One line on what the scenario asks for: "coupled run, 6 blocks, 2 flow boundaries".
std::string describe(const scenario::Scenario& scenario);

}  // namespace hydrodda::cli
