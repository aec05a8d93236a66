#pragma once
// The diagnostics reading a scenario text gives, for the reader's tests: none when it reads.

#include <string>
#include <vector>

#include "scenario/diagnostics.hpp"
#include "scenario/reader.hpp"

namespace hydrodda::scenario::test_support {

inline std::vector<Diagnostic> errors_of(const std::string& text) {
  try {
    parse_scenario(text, "case.toml");
  } catch (const ScenarioError& e) {
    return e.diagnostics();
  }
  return {};
}

}  // namespace hydrodda::scenario::test_support
