#pragma once
// Input errors found while reading a scenario, collected so that all are reported together.

#include <stdexcept>
#include <string>
#include <vector>

namespace hydrodda::scenario {

struct Diagnostic {
  std::string file;
  int line = 0;          // 0 when no line applies
  std::string key;       // dotted key path, e.g. material.rock.young
  std::string message;

  // "scenario.toml:12: material.rock.young: must be > 0"
  std::string format() const;
};

// Thrown when a scenario has one or more errors; what() lists them all, one per line.
class ScenarioError : public std::runtime_error {
 public:
  explicit ScenarioError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

// The closest candidate by edit distance, or "" when none is close enough to be a likely typo.
std::string suggest_nearest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace hydrodda::scenario
