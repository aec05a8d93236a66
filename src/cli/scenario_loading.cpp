#include "cli/scenario_loading.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cstdio>

#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::cli {

namespace {

template <class Read>
std::optional<scenario::Scenario> load_with(const std::filesystem::path& file, Read read) {
  try {
    scenario::Scenario s = read();
    for (const scenario::DefaultUsed& d : s.defaults_used)
      spdlog::debug("default used: {} = {}", d.key, d.value);
    if (!s.defaults_used.empty() && !spdlog::should_log(spdlog::level::debug))
      spdlog::info("{} default value(s) used (-v lists them)", s.defaults_used.size());
    return s;
  } catch (const scenario::ScenarioError& e) {
    print_scenario_errors(file, e);
    return std::nullopt;
  }
}

}  // namespace

void print_scenario_errors(const std::filesystem::path& file, const scenario::ScenarioError& error) {
  for (const scenario::Diagnostic& d : error.diagnostics())
    std::fputs(fmt::format("error: {}\n", d.format()).c_str(), stderr);
  std::fputs(fmt::format("{}: {} error(s)\n", file.string(), error.diagnostics().size()).c_str(), stderr);
}

std::optional<scenario::Scenario> load_scenario(const std::filesystem::path& file) {
  return load_with(file, [&] { return scenario::read_scenario(file); });
}

std::optional<scenario::Scenario> load_scenario_text(std::string_view text, const std::filesystem::path& file) {
  return load_with(file, [&] { return scenario::parse_scenario(text, file); });
}

std::string describe(const scenario::Scenario& s) {
  const char* kind = s.mechanics && s.flow ? "coupled run" : s.mechanics ? "mechanics only" : "flow only";
  std::string text = kind;
  if (s.geometry) {
    // A domain's traces and blocks are counted once it is cut (check_model).
    if (!s.geometry->blocks.empty()) text += fmt::format(", {} blocks", s.geometry->blocks.size());
  }
  if (s.flow) text += fmt::format(", {} flow boundaries", s.flow->boundaries.size());
  return text;
}

}  // namespace hydrodda::cli
