#include "sweep/preparation.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "run/run.hpp"
#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"
#include "sweep/results.hpp"

namespace hydrodda::sweep {

namespace fs = std::filesystem;

namespace {

// A TOML basic string holding `text`.
std::string toml_string(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

// "Six-block model — head at base = 5 m, density = 2000 kg/m³".
std::string case_title(const std::string& base_title, const std::vector<scenario::Override>& values,
                       const std::vector<std::string>& boundary_names) {
  std::string text;
  for (const scenario::Override& o : values)
    text += fmt::format("{}{}", text.empty() ? "" : ", ", value_label(o, boundary_names));
  return base_title.empty() ? text : base_title + " — " + text;
}

}  // namespace

std::string describe_case(const std::vector<scenario::Override>& overrides) {
  std::string text;
  for (const scenario::Override& o : overrides) text += fmt::format("{}{}={}", text.empty() ? "" : ", ", o.key, o.value);
  return text;
}

std::vector<std::string> boundary_names_of(const scenario::Scenario& s) {
  std::vector<std::string> names;
  if (s.flow)
    for (const scenario::FlowBoundaryCondition& b : s.flow->boundaries) names.push_back(b.name);
  return names;
}

Preparation prepare_cases(const fs::path& file, const fs::path& directory,
                          const std::vector<std::vector<scenario::Override>>& cases, const scenario::Scenario& base,
                          const std::function<bool()>& stop_requested) {
  const std::vector<std::string> boundary_names = boundary_names_of(base);
  const std::string original = run::read_text_file(file).value_or("");
  Preparation prepared;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (stop_requested()) {
      prepared.interrupted = true;
      break;
    }
    const std::string name = fmt::format("case_{:03}", i);
    const fs::path case_file = directory / name / "scenario.toml";
    std::string text;
    try {
      // The case's title names its values, so that its figures say which case they show.
      std::vector<scenario::Override> overrides = cases[i];
      overrides.push_back({"title", toml_string(case_title(base.title, cases[i], boundary_names))});
      text = scenario::apply_overrides(original, file, overrides);
      const scenario::Scenario s = scenario::parse_scenario(text, case_file);
      run::check_model(s);  // as `check` does
      if (i == 0 && s.flow)
        for (const scenario::FlowRegion& r : s.flow->regions) prepared.region_names.push_back(r.name);
      prepared.cases.push_back({name, std::move(text)});
      spdlog::debug("{} ({}): checked", name, describe_case(cases[i]));
    } catch (const scenario::ScenarioError& e) {
      prepared.errors.push_back(fmt::format("{} ({}):", name, describe_case(cases[i])));
      // Cited in the scenario file and the --set the user wrote: the case's file is not kept.
      for (const scenario::Diagnostic& d :
           scenario::locate_in_original(e.diagnostics(), text, case_file, original, file, cases[i]))
        prepared.errors.push_back(d.format());
    }
  }
  return prepared;
}

}  // namespace hydrodda::sweep
